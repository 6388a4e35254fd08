#!/usr/bin/env bash
# Light selection strategies at equal time on scenes with many emitters of very different
# power: the light BVH ("bvh", pbrt-v4's default: importance at the receiving point) against
# selection by power alone ("power"). Prints wall time and relMSE against a high-spp
# reference for each, and the error ratio power/bvh at equal time (relMSE falls as 1/time).
#   bench/light_samplers.sh [spp]   (default 16)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_BUILD_DIR:-$root/build}"
kiln="$build/kiln"
spp="${1:-16}"
for scene in hot-spot-mesh hot-spots-mesh many-lights; do
    out="$root/bench/out/light-samplers/$scene"
    mkdir -p "$out"
    file="$root/bench/scenes/$scene.pbrt"
    [ -f "$out/ref.exr" ] || "$kiln" "$file" --spp 2048 --seed 12345 --quiet -o "$out/ref.exr"
    declare -A err secs
    for ls in bvh power; do
        line=$("$kiln" "$file" --spp "$spp" --light-sampler "$ls" -o "$out/$ls.exr" 2>&1 | grep "wall")
        secs[$ls]=$(echo "$line" | sed 's/.* spp, \([0-9.]*\)s wall.*/\1/')
        err[$ls]=$("$build/bench/kiln_benchtool" relmse "$out/ref.exr" "$out/$ls.exr" | awk '{print $2}')
        printf "%-14s %-6s %6.2f s  relMSE %.4g\n" "$scene" "$ls" "${secs[$ls]}" "${err[$ls]}"
    done
    ratio=$(echo "${err[power]} * ${secs[power]} / (${err[bvh]} * ${secs[bvh]})" | bc -l)
    printf "%-14s power/bvh error ratio at equal time: %.2f\n" "$scene" "$ratio"
done
