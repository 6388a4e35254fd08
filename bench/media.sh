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
source "$root/bench/compare_lib.sh"
build_revision "$root" "$rev" "$root/build-base-media"
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
