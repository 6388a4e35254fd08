#!/usr/bin/env bash
# What polarised transport costs scenes that do not use it, and what it costs those that do:
# renders scenes with kiln as built (build/) and with kiln built at an earlier revision (before
# polarisation; default 93d61a1, checked out into build-base/src with git worktree and built in
# build-base/ if missing), alternating the binaries on one thread, and prints the ratios of the
# median render-loop times (kiln's "s wall" line, loading excluded). Then the same scenes with
# --stokes (the polarised variant) against plain, both with build/.
#   bench/polarization_overhead.sh [repeats] [base revision]   (defaults 5, 93d61a1)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
now="${KILN_BUILD_DIR:-$root/build}/kiln"
repeats="${1:-5}"
rev="${2:-93d61a1}"
base="$root/build-base/kiln"
if [ ! -x "$base" ]; then
    [ -d "$root/build-base/src" ] || git -C "$root" worktree add --detach "$root/build-base/src" "$rev"
    cmake -S "$root/build-base/src" -B "$root/build-base" -DCMAKE_BUILD_TYPE=Release \
        -DKILN_BENCH=OFF >/dev/null
    cmake --build "$root/build-base" -j "$(nproc)" --target kiln >/dev/null
fi
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
render_time() {  # binary scene spp [options]: seconds of the render loop
    local binary="$1" scene="$2" spp="$3"
    shift 3
    "$binary" "$scene" --spp "$spp" --threads 1 -o /tmp/kiln-polarization.exr "$@" 2>&1 |
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
scenes=("cornell-box/cornell-box 16" "textured-meshes/textured-meshes 8"
        "wilkie2011/gold-kirchhoff-ambient 8" "thermal/lava 8")
for s in "${scenes[@]}"; do
    read -r scene spp <<< "$s"
    compare "unpolarised: now / before" "$root/scenes/$scene.pbrt" "$spp" "$now" "" "$base" ""
done
for s in "${scenes[@]}"; do
    read -r scene spp <<< "$s"
    compare "polarised (--stokes) / unpolarised" "$root/scenes/$scene.pbrt" "$spp" "$now" \
        "--stokes" "$now" ""
done
