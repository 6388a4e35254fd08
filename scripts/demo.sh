#!/usr/bin/env bash
# Renders the first showcase scene (scenes/showcase/forge.pbrt: a steel bar at a yellow heat on
# an anvil) twice, with Kirchhoff's law (kiln's default) and with the additive model many
# renderers use, and puts the two side by side in out/demo.png (left Kirchhoff, right
# additive); the linear renders are out/forge-kirchhoff.exr and out/forge-additive.exr. About
# a minute on 2 cores. Installs the packages building and rendering need and builds kiln first
# when needed (scripts/test.sh installs the rest). Extra arguments go to kiln, e.g. --spp 64;
# KILN_OUT_DIR puts the images elsewhere than out/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
KILN_SETUP=render "$root/scripts/bootstrap.sh" --target kiln
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
out="${KILN_OUT_DIR:-$root/out}"
mkdir -p "$out"
for model in kirchhoff additive; do
    echo "kiln: rendering with $model emission" >&2
    "$kiln" "$root/scenes/showcase/forge.pbrt" --spp 16 --emission "$model" \
        -o "$out/forge-$model.exr" "$@"
done
"$kiln" convert "$out/forge-kirchhoff.exr" "$out/forge-additive.exr" -o "$out/demo.png"
echo "kiln: $out/demo.png (left: Kirchhoff's law, right: additive emission)" >&2
