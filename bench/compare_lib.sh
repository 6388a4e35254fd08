# Sourced by the scripts that time one kiln binary against another (or against itself with
# other options): render-loop seconds (kiln's "s wall" line, loading excluded) on one thread,
# medians over $repeats alternating runs.
#   compare LABEL SCENE SPP BINARY_A "ARGS_A" BINARY_B "ARGS_B"   prints A / B
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
render_time() {  # binary scene spp [options]: seconds of the render loop
    local binary="$1" scene="$2" spp="$3"
    shift 3
    "$binary" "$scene" --spp "$spp" --threads 1 -o /tmp/kiln-compare.exr "$@" 2>&1 |
        sed -n 's/.* \([0-9.]*\)s wall.*/\1/p'
}
compare() {  # label scene spp binaryA argsA binaryB argsB (args as one word, may be empty)
    local label="$1" scene="$2" spp="$3" a="$4" aArgs="$5" b="$6" bArgs="$7"
    : > /tmp/kiln-a.txt
    : > /tmp/kiln-b.txt
    for _ in $(seq "$repeats"); do
        # shellcheck disable=SC2086
        render_time "$a" "$scene" "$spp" $aArgs >> /tmp/kiln-a.txt
        # shellcheck disable=SC2086
        render_time "$b" "$scene" "$spp" $bArgs >> /tmp/kiln-b.txt
    done
    local ta tb
    ta=$(median < /tmp/kiln-a.txt)
    tb=$(median < /tmp/kiln-b.txt)
    printf "%-26s %-34s %7.3f s / %7.3f s = %.4f\n" "$(basename "$scene" .pbrt)" "$label" \
        "$ta" "$tb" "$(echo "$ta / $tb" | bc -l)"
}
# Builds kiln at revision rev in dir (a git worktree in dir/src) unless dir/kiln exists.
build_revision() {  # root rev dir
    local root="$1" rev="$2" dir="$3"
    [ -x "$dir/kiln" ] && return 0
    [ -d "$dir/src" ] || git -C "$root" worktree add --detach "$dir/src" "$rev"
    cmake -S "$dir/src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DKILN_BENCH=OFF >/dev/null
    cmake --build "$dir" -j "$(nproc)" --target kiln >/dev/null
}
