#!/usr/bin/env bash
# Package the Blender add-on for Preferences > Add-ons > Install:
#   blender/make_zip.sh OUT.zip
# OUT.zip holds kiln_blender/*.py (no caches). Needs python3 (its zipfile module).
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 OUT.zip" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
out="$1"
python3 - "$here" "$out" <<'PY'
import os, sys, zipfile
here, out = sys.argv[1], sys.argv[2]
package = os.path.join(here, "kiln_blender")
with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
    for name in sorted(os.listdir(package)):
        if name.endswith(".py"):
            archive.write(os.path.join(package, name), "kiln_blender/" + name)
print("wrote %s" % out)
PY
