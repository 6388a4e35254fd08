#!/usr/bin/env bash
# kiln installed elsewhere renders: `cmake --install` into a fresh prefix, and the Debian package
# that `cpack -G DEB` builds, unpacked into a fresh root and (as root, when no kiln package is
# installed) installed with dpkg -i and removed again, each run from an unrelated working
# directory. Each must find its plugins and display config in its own tree (kiln --version
# says where), render a PNG (display config) and a JPEG (OpenImageIO plugin), and the package
# must depend only on Debian 12 packages that are installed here (what apt installs with it).
# With KILN_TEST_PYTHON set (the Python the module was built for), the Python module in each
# tree renders too.
#   package_test.sh BUILD_DIR
set -euo pipefail
build="$(cd "$1" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/scene.pbrt" <<'SCENE'
Film "rgb" "integer xresolution" 24 "integer yresolution" 16
Sampler "independent" "integer pixelsamples" 2
LookAt 0 0 -4 0 0 0 0 1 0
Camera "perspective"
WorldBegin
Material "conductor" "float temperature" 1400
Shape "sphere"
SCENE
fail() { echo "package_test: $*" >&2; exit 1; }

# Renders with the kiln at $1 from an unrelated folder; its run-time files must lie under $2
check_tree() {
    local kiln="$1" tree="$2" out="$tmp/out-$(basename "$2")"
    mkdir -p "$out"
    (cd / && "$kiln" --version) >"$out/version.txt"
    grep -q "display config: $tree/" "$out/version.txt" || fail "$kiln: config not in $tree: $(cat "$out/version.txt")"
    [ "$(grep -c "plugin: $tree/" "$out/version.txt")" = 2 ] || fail "$kiln: plugins not in $tree: $(cat "$out/version.txt")"
    (cd / && "$kiln" "$tmp/scene.pbrt" --quiet -o "$out/a.png" -o "$out/a.jpg" -o "$out/a.exr") ||
        fail "$kiln could not render"
    for f in a.png a.jpg a.exr; do [ -s "$out/$f" ] || fail "$kiln wrote no $f"; done
    # The Python module, when built: imported from the tree (PYTHONPATH; Debian's Python
    # searches <prefix>/lib/python3.X/dist-packages itself for /usr and /usr/local), it finds
    # its plugins and display config in the tree too
    local python="${KILN_TEST_PYTHON:-}" pydir
    pydir="$(ls -d "$tree"/lib/python3*/dist-packages 2>/dev/null | head -1)"
    if [ -n "$python" ]; then
        [ -f "$pydir/kiln/__init__.py" ] || fail "no Python module under $tree/lib"
        (cd / && PYTHONPATH="$pydir" "$python" -c "
import kiln, sys
assert kiln.__file__.startswith('$tree/'), kiln.__file__
assert kiln._kiln._install_prefix() == '$tree', kiln._kiln._install_prefix()
scene = kiln.load('$tmp/scene.pbrt')
img = scene.render(spp=2)
assert img.shape == (16, 24, 3) and img.max() > 0
scene.write('$out/py.png'); scene.write('$out/py.jpg')
") || fail "the Python module in $tree could not render"
        for f in py.png py.jpg; do [ -s "$out/$f" ] || fail "the Python module wrote no $f"; done
    fi
}

# 1. cmake --install into a prefix
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
check_tree "$tmp/prefix/bin/kiln" "$tmp/prefix"

# 2. The Debian package, unpacked
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$tmp/deb" >/dev/null
deb="$(ls "$tmp"/deb/kiln_*.deb)"
dpkg-deb -x "$deb" "$tmp/root"
check_tree "$tmp/root/usr/bin/kiln" "$tmp/root/usr"
depends="$(dpkg-deb -f "$deb" Depends)"
[ -n "$depends" ] || fail "the package declares no dependencies"
# Every dependency (name before any version) is a Debian package installed here
IFS=',' read -ra deps <<<"$depends"
for d in "${deps[@]}"; do
    name="$(echo "$d" | sed -e 's/^ *//' -e 's/ .*//')"
    dpkg-query -W -f='${Status}' "$name" 2>/dev/null | grep -q "install ok installed" ||
        fail "dependency $name is not an installed package"
done
# 3. The Debian package, installed by dpkg (which refuses it if a dependency is missing) and
# removed again: only as root, and only where no kiln package is installed already
installed=""
if [ "$(id -u)" = 0 ] && ! dpkg-query -W -f='${Status}' kiln 2>/dev/null | grep -q "ok installed"; then
    trap 'dpkg -r kiln >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT
    dpkg -i "$deb" >"$tmp/dpkg.txt" 2>&1 || fail "dpkg -i refused the package: $(cat "$tmp/dpkg.txt")"
    check_tree /usr/bin/kiln /usr
    dpkg -r kiln >/dev/null || fail "dpkg -r kiln failed"
    [ ! -e /usr/bin/kiln ] || fail "dpkg -r left /usr/bin/kiln"
    installed=", installed by dpkg -i and removed"
else
    echo "package_test: not installing the package (needs root and no kiln package installed)" >&2
fi
echo "package_test: install tree and $(basename "$deb") render (${#deps[@]} dependencies$installed)"
