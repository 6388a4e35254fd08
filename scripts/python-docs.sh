#!/usr/bin/env bash
# Makes docs/python.md's pictures: runs its Python blocks (scripts/run_python_doc.py) with the
# module built in build/python and copies the PNGs they save into docs/images.
#   scripts/python-docs.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
PYTHONPATH="${KILN_BUILD_DIR:-$root/build}/python" /usr/bin/python3 \
    "$root/scripts/run_python_doc.py" "$root/docs/python.md" "$out"
cp "$out"/python-*.png "$root/docs/images/"
ls "$out"/python-*.png | sed 's|.*/|docs/images/|'
