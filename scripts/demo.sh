#!/usr/bin/env bash
# Renders the demo scene to out/demo.exr and out/demo.png (installing the packages rendering
# needs and building kiln first when needed; scripts/test.sh installs the rest). Extra arguments go to kiln, e.g. --spp 16.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
KILN_SETUP=render "$root/scripts/bootstrap.sh" --target kiln
mkdir -p "$root/out"
"${KILN_BUILD_DIR:-$root/build}/kiln" "$root/scenes/demo.pbrt" \
    --spp 32 -o "$root/out/demo.exr" -o "$root/out/demo.png" "$@"
