#!/usr/bin/env bash
# Points on a hot shape whose temperature varies over it, sampled in proportion to emitted
# power (kiln's default) against the shape's own sampling (uniform area, or the cone of a
# sphere): relMSE against a high-spp reference and the error ratio at equal time, on a heat-
# mapped bilinear patch and a sphere with a hot cap.
#   bench/emitter_sampling.sh [spp]   (default 16)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${KILN_BUILD_DIR:-$root/build}"
kiln="$build/kiln"
spp="${1:-16}"
for scene in heat-mapped-emitter gradient-sphere; do
    out="$root/bench/out/emitter-sampling/$scene"
    mkdir -p "$out"
    file="$root/bench/scenes/$scene.pbrt"
    [ -f "$out/ref.exr" ] || "$kiln" "$file" --spp 2048 --seed 12345 --quiet -o "$out/ref.exr"
    declare -A err secs
    for es in power shape; do
        line=$("$kiln" "$file" --spp "$spp" --emitter-sampling "$es" -o "$out/$es.exr" 2>&1 |
            grep "wall")
        secs[$es]=$(echo "$line" | sed 's/.* spp, \([0-9.]*\)s wall.*/\1/')
        err[$es]=$("$build/bench/kiln_benchtool" relmse "$out/ref.exr" "$out/$es.exr" |
            awk '{print $2}')
        printf "%-20s %-6s %6.2f s  relMSE %.4g\n" "$scene" "$es" "${secs[$es]}" "${err[$es]}"
    done
    ratio=$(echo "${err[shape]} * ${secs[shape]} / (${err[power]} * ${secs[power]})" | bc -l)
    printf "%-20s shape/power error ratio at equal time: %.2f\n" "$scene" "$ratio"
done
