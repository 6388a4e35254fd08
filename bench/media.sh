#!/usr/bin/env bash
# Participating media.
# 1. What media support costs scenes without media: kiln as built (build/) against kiln built
#    before media (default fc9f79a, checked out into build-base-media/src with git worktree and
#    built in build-base-media/ if missing), and --generic volpath (the volumetric integrator
#    run anyway) against the path integrator kiln chooses for them. Medians of the render-loop
#    time (kiln's "s wall", loading excluded) on one thread, the binaries alternating.
# 2. The volumetric scenes (scenes/media/): render time and relMSE against a 1024-spp reference
#    (cached in bench/out/media/) at 4, 16 and 64 spp, over the central quarter of the image.
#   bench/media.sh [repeats] [base revision]   (defaults 5, fc9f79a)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_BUILD_DIR:-$root/build}"
now="$build/kiln"
repeats="${1:-5}"
rev="${2:-fc9f79a}"
base="$root/build-base-media/kiln"
if [ ! -x "$base" ]; then
    [ -d "$root/build-base-media/src" ] ||
        git -C "$root" worktree add --detach "$root/build-base-media/src" "$rev"
    cmake -S "$root/build-base-media/src" -B "$root/build-base-media" -DCMAKE_BUILD_TYPE=Release \
        -DKILN_BENCH=OFF >/dev/null
    cmake --build "$root/build-base-media" -j "$(nproc)" --target kiln >/dev/null
fi
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
render_time() {  # binary scene spp [options]: seconds of the render loop
    local binary="$1" scene="$2" spp="$3"
    shift 3
    "$binary" "$scene" --spp "$spp" --threads 1 -o /tmp/kiln-media.exr "$@" 2>&1 |
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
    compare "no media: now / before media" "$root/scenes/$scene.pbrt" "$spp" "$now" "" "$base" ""
done
for s in "${scenes[@]}"; do
    read -r scene spp <<< "$s"
    compare "--generic volpath / path" "$root/scenes/$scene.pbrt" "$spp" "$now" \
        "--generic volpath" "$now" ""
done

# Time against error on the volumetric scenes
crop="--crop 0.25 0.75 0.25 0.75"
for scene in glass-blowing quartz-ring-smoky lava-smoke; do
    out="$root/bench/out/media/$scene"
    mkdir -p "$out"
    file="$root/scenes/media/$scene.pbrt"
    # shellcheck disable=SC2086
    [ -f "$out/ref.exr" ] || "$now" "$file" --spp 1024 --seed 12345 $crop --quiet -o "$out/ref.exr"
    for spp in 4 16 64; do
        # shellcheck disable=SC2086
        secs=$("$now" "$file" --spp "$spp" $crop -o "$out/$spp.exr" 2>&1 |
            sed -n 's/.* \([0-9.]*\)s wall.*/\1/p')
        err=$("$build/bench/kiln_benchtool" relmse "$out/ref.exr" "$out/$spp.exr" | awk '{print $2}')
        printf "%-20s %3d spp %7.2f s  relMSE %.4g\n" "$scene" "$spp" "$secs" "$err"
    done
done
