#!/usr/bin/env bash
# The Blender add-on's tests, headless:
#   test/blender/run_tests.sh BUILD_DIR SOURCE_DIR [PBRT_V4_BINARY]
# 1. packs blender/kiln_blender into a zip (blender/make_zip.sh) and installs and enables it
#    with bpy.ops.preferences.addon_install / addon_enable in a temporary BLENDER_USER_SCRIPTS;
# 2. runs test/blender/addon_test.py with BUILD_DIR/kiln (and pbrt-v4 if given; also taken
#    from the environment variable PBRT_V4_BINARY);
# 3. renders the .blend the test saved with the kiln engine from the command line
#    (blender -b FILE --addons kiln_blender -E KILN -o OUT -f 1) and checks that the image
#    exists and is not black.
# Needs `blender` on PATH (or BLENDER=...). Exit status 0 only if everything passes.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 BUILD_DIR SOURCE_DIR [PBRT_V4_BINARY]" >&2; exit 2; }
build="$(cd "$1" && pwd)"
source="$(cd "$2" && pwd)"
pbrt="${3:-${PBRT_V4_BINARY:-}}"
blender="${BLENDER:-blender}"
kiln="$build/kiln"
fail() { echo "run_tests: FAIL: $*" >&2; exit 1; }
[ -x "$kiln" ] || fail "no kiln executable at $kiln"
command -v "$blender" >/dev/null || fail "no blender ($blender)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
started=$(date +%s.%N)

echo "== packing and installing the add-on"
"$source/blender/make_zip.sh" "$tmp/kiln_blender.zip"
export BLENDER_USER_SCRIPTS="$tmp/scripts"
"$blender" -b --factory-startup --python-exit-code 1 --python-expr "
import bpy, os
bpy.ops.preferences.addon_install(filepath='$tmp/kiln_blender.zip')
bpy.ops.preferences.addon_enable(module='kiln_blender')
import kiln_blender
assert os.path.dirname(kiln_blender.__file__) == os.path.join('$tmp/scripts', 'addons', 'kiln_blender'), kiln_blender.__file__
assert 'KILN' in {e.bl_idname for e in bpy.types.RenderEngine.__subclasses__()}
print('run_tests: installed and enabled', kiln_blender.__file__)
" >"$tmp/install.log" 2>&1 || fail "installing the add-on: $(tail -n 20 "$tmp/install.log")"
grep "run_tests:" "$tmp/install.log"

echo "== addon_test.py"
KILN_BLENDER_REQUIRE_INSTALLED=1 "$blender" -b --factory-startup --python-exit-code 1 \
    --python "$source/test/blender/addon_test.py" -- "$kiln" "$pbrt" "$tmp/work" \
    >"$tmp/test.log" 2>&1 || { grep -v "^$" "$tmp/test.log" | tail -n 60; fail "addon_test.py"; }
grep -E "^(ok|FAIL|note|   |--|addon_test)" "$tmp/test.log"

echo "== headless render: blender -b scene.blend --addons kiln_blender -E KILN -o OUT -f 1"
KILN_EXECUTABLE="$kiln" "$blender" -b "$tmp/work/scene.blend" --addons kiln_blender -E KILN \
    -o "$tmp/out/frame_####" -f 1 >"$tmp/render.log" 2>&1 \
    || { tail -n 30 "$tmp/render.log"; fail "the headless render"; }
image="$(ls "$tmp"/out/frame_0001.* 2>/dev/null | head -n 1 || true)"
[ -n "$image" ] || { tail -n 30 "$tmp/render.log"; fail "no image written by the headless render"; }
if grep -q "kiln exited\|kiln: no kiln executable\|Error: kiln" "$tmp/render.log"; then
    tail -n 30 "$tmp/render.log"; fail "kiln reported an error during the headless render"
fi
"$blender" -b --factory-startup --python-exit-code 1 --python-expr "
import bpy, numpy as np
image = bpy.data.images.load('$image')
w, h = image.size
pixels = np.empty(w * h * 4, np.float32); image.pixels.foreach_get(pixels)
rgb = pixels.reshape(h, w, 4)[:, :, :3]
print('run_tests: %s: %dx%d, brightest pixel %.3f, %d pixels above 0.02' % ('$(basename "$image")', w, h, rgb.max(), int((rgb.max(axis=2) > 0.02).sum())))
assert (w, h) == (96, 72), (w, h)
assert rgb.max() > 0.1, 'the image is black'
" >"$tmp/check.log" 2>&1 || { cat "$tmp/check.log"; fail "the headless render's image"; }
grep "run_tests:" "$tmp/check.log"

# 4. The add-on linked from the source tree, with no kiln named anywhere (no KILN_EXECUTABLE,
#    none on PATH): it runs the tree's own build/kiln (when BUILD_DIR is SOURCE_DIR/build)
if [ "$build" = "$source/build" ]; then
    echo "== the add-on linked from the source tree runs the tree's build/kiln"
    mkdir -p "$tmp/linked/addons"
    ln -s "$source/blender/kiln_blender" "$tmp/linked/addons/kiln_blender"
    (unset KILN_EXECUTABLE; BLENDER_USER_SCRIPTS="$tmp/linked" PATH="$(dirname "$(command -v "$blender")"):/usr/bin:/bin" \
        "$blender" -b "$tmp/work/scene.blend" --addons kiln_blender -E KILN \
        -o "$tmp/linked-out/frame_####" -f 1) >"$tmp/linked.log" 2>&1 ||
        { tail -n 30 "$tmp/linked.log"; fail "the linked add-on's render"; }
    [ -s "$tmp/linked-out/frame_0001.png" ] && ! grep -q "no kiln executable\|kiln exited" "$tmp/linked.log" ||
        { tail -n 30 "$tmp/linked.log"; fail "the linked add-on did not render with build/kiln"; }
    echo "run_tests: rendered frame_0001.png with $source/build/kiln"
fi
echo "run_tests: all passed in $(python3 -c "print('%.1f' % ($(date +%s.%N) - $started))") s"
