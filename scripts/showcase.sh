#!/usr/bin/env bash
# Renders the showcase scenes (scenes/showcase/) at full size into docs/images/showcase-*.png,
# each with a line of what it took (spp, resolution, render time, machine) in
# docs/images/showcase-*.txt, which README.md quotes.
# Usage: scripts/showcase.sh [spp [scene ...]]   (default 256; scenes: forge bulbs pour)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kiln="${KILN_BUILD_DIR:-$root/build}/kiln"
spp="${1:-256}"
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(forge bulbs pour)
out="$root/docs/images"
mkdir -p "$out"
for scene in "${scenes[@]}"; do
    log="$(mktemp)"
    file="$root/scenes/showcase/$scene.pbrt"
    [ -f "$file" ] || file="$file.gz"  # the bulbs are gzip-compressed
    "$kiln" "$file" --spp "$spp" -o "$out/showcase-$scene.png" 2>"$log"
    # kiln's last line: "kiln: 1280x720, 256 spp, 123.45s wall, 1.23 Mpaths/s"
    summary="$(tail -n 1 "$log" | sed 's/^kiln: //')"
    rm -f "$log"
    echo "$summary on $(nproc) cores ($(date -u +%Y-%m-%d), kiln $(git -C "$root" rev-parse --short HEAD))" \
        >"$out/showcase-$scene.txt"
    echo "$scene: $summary"
done
