#!/usr/bin/env bash
# Renders the small images shown in README.md ("Glowing objects") into docs/images/.
# Usage: scripts/readme-images.sh [spp] [all|thermal]   (default 64 all)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
spp="${1:-64}"
out="$root/docs/images"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"
render() {  # scene output.png [extra kiln args]
    local scene="$1" png="$2"
    shift 2
    "$kiln" "$scene" --spp "$spp" --quiet -o "$png" "$@"
}
if [ "${2:-all}" = all ]; then
for material in silver gold; do
    for model in additive kirchhoff; do
        render "$root/scenes/wilkie2011/$material-$model-ambient.pbrt" "$tmp/$material-$model.png"
    done
    # Side by side: additive (left) vs kirchhoff (right), half size.
    oiiotool "$tmp/$material-additive.png" "$tmp/$material-kirchhoff.png" --mosaic 2x1 \
        --resize 50% -o "$out/$material-additive-vs-kirchhoff.png"
done
render "$root/scenes/coins/coins.pbrt" "$tmp/coins.png"
oiiotool "$tmp/coins.png" --resize 66.67% -o "$out/coins.png"
fi
# Temperature fields (scenes/thermal/): gradient, per-vertex lava, heat map, cooling blade
for scene in heated-bar lava heat-map; do
    render "$root/scenes/thermal/$scene.pbrt" "$tmp/$scene.png"
done
oiiotool "$tmp/heated-bar.png" "$tmp/lava.png" --mosaic 2x1 --resize 50% \
    -o "$out/heated-bar-and-lava.png"
oiiotool "$tmp/heat-map.png" --resize 50% -o "$out/heat-map.png"
"$kiln" "$root/scenes/thermal/cooling-blade.pbrt" --spp "$spp" --quiet --frames 0-48 --fps 12 \
    -o "$tmp/blade.####.png"
oiiotool "$tmp/blade.0000.png" "$tmp/blade.0024.png" "$tmp/blade.0048.png" --mosaic 3x1 \
    --resize 50% -o "$out/cooling-blade.png"
