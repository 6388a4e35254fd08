#!/usr/bin/env bash
# What kiln's load-time choices save (SceneFeatures, kiln --verbose): each scene is rendered
# with the code paths chosen for it and with one generic path at a time (kiln --generic
# footprints: texture footprints at every hit instead of only at surfaces whose textures filter
# with them; --generic aovs: first-hit AOV work for every camera ray instead of only when the
# film writes AOVs), alternating them, and the ratio of median render-loop times is printed. The
# third choice, no thermal code for scenes without hot shapes, is measured by
# bench/thermal_overhead.sh (a build without it).
#   bench/specialisation.sh [repeats]   (default 5)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
repeats="${1:-5}"
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
render_seconds() {  # scene spp [flags]: the render loop's wall time from kiln's summary line
    "$kiln" "$1" --spp "$2" --threads 2 -o /tmp/kiln-specialisation.exr "${@:3}" 2>&1 |
        grep "wall" | sed 's/.* spp, \([0-9.]*\)s wall.*/\1/'
}
for scene in cornell-box/cornell-box textured-meshes/textured-meshes thermal/lava; do
    file="$root/scenes/$scene.pbrt"
    : > /tmp/kiln-chosen.txt
    : > /tmp/kiln-footprints.txt
    : > /tmp/kiln-aovs.txt
    for _ in $(seq "$repeats"); do
        render_seconds "$file" 16 >> /tmp/kiln-chosen.txt
        render_seconds "$file" 16 --generic footprints >> /tmp/kiln-footprints.txt
        render_seconds "$file" 16 --generic aovs >> /tmp/kiln-aovs.txt
    done
    c=$(median < /tmp/kiln-chosen.txt)
    f=$(median < /tmp/kiln-footprints.txt)
    a=$(median < /tmp/kiln-aovs.txt)
    printf "%-34s chosen %6.2f s | footprints everywhere %6.2f s (%.3f) | AOVs always %6.2f s (%.3f)\n" \
        "$scene" "$c" "$f" "$(echo "$f / $c" | bc -l)" "$a" "$(echo "$a / $c" | bc -l)"
done
