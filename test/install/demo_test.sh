#!/usr/bin/env bash
# README's first command works: scripts/demo.sh (with the build under test, at 1 sample per pixel
# to stay quick) renders the forge with Kirchhoff's law and with additive emission and puts the
# two side by side in demo.png, twice the scene's width.
#   demo_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
root="$(cd "$1" && pwd)"
build="$(cd "$2" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "demo_test: $*" >&2; exit 1; }
KILN_BUILD_DIR="$build" KILN_OUT_DIR="$tmp" "$root/scripts/demo.sh" --spp 1 --quiet \
    >"$tmp/log.txt" 2>&1 || fail "scripts/demo.sh failed: $(tail -n 20 "$tmp/log.txt")"
for f in forge-kirchhoff.exr forge-additive.exr demo.png; do
    [ -s "$tmp/$f" ] || fail "no $f"
done
"$build/kiln" info "$tmp/demo.png" >"$tmp/info.txt"
grep -q "2560 x 720\|2560x720" "$tmp/info.txt" || fail "demo.png is not two 1280x720 renders: $(cat "$tmp/info.txt")"
echo "demo_test: scripts/demo.sh wrote $(head -n 1 "$tmp/info.txt")"
