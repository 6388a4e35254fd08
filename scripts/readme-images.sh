#!/usr/bin/env bash
# Renders the small images shown in README.md ("Glowing objects") into docs/images/.
# Usage: scripts/readme-images.sh [spp]   (default 64)
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
