#!/usr/bin/env bash
# Installs the add-on for the current user's Blender: links blender/kiln_blender into Blender's
# user add-on folder (BLENDER_USER_SCRIPTS/addons when that is set, else the folder Blender
# reports, e.g. ~/.config/blender/3.4/scripts/addons) and enables it in the saved preferences.
# Linked from this tree, the add-on runs this tree's build/kiln unless told otherwise
# (docs/blender.md). Afterwards `blender -b FILE.blend -E KILN -o OUT -f 1` renders with kiln.
#   blender/install.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
blender="${BLENDER:-blender}"
command -v "$blender" >/dev/null || { echo "install.sh: no blender on PATH" >&2; exit 1; }
status=0
log="$("$blender" -b --factory-startup --python-exit-code 1 --python-expr "
import bpy, os, sys
addons = bpy.utils.user_resource('SCRIPTS', path='addons', create=True)
target = os.path.join(addons, 'kiln_blender')
source = '$here/kiln_blender'
if os.path.islink(target):
    os.remove(target)
elif os.path.exists(target):
    sys.exit('install.sh: %s exists and is not a link: remove it first' % target)
os.symlink(source, target)
bpy.utils.refresh_script_paths()
bpy.ops.preferences.addon_enable(module='kiln_blender')
bpy.ops.wm.save_userpref()
print('install.sh: linked %s -> %s and enabled it' % (target, source))
" 2>&1)" || status=$?
if [ "$status" -ne 0 ]; then echo "$log" >&2; exit "$status"; fi
echo "$log" | grep "^install.sh:"
