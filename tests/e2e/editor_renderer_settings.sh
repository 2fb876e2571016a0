#!/usr/bin/env bash
# editor_renderer_settings.sh STOA_EDITOR SOURCE_DIR WORK_DIR
# stoa-editor draws a scene file's renderer settings headless: the example
# scene forward, deferred (lab 08), deferred with ambient occlusion (lab 09)
# and the G-buffer's normals. The normals view shows the floor's up-facing
# normal (green the strongest channel), deferred lights the floor as forward
# does, and ambient occlusion darkens the floor at the column's foot
# (under a strong ambient light, which is what it darkens).
set -euo pipefail
program=$1 source=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
cd "$work"

fail() { echo "FAIL: $*"; exit 1; }

# scene NAME DEFERRED SSAO VIEW: the example with those settings, rendered to NAME.png
scene() {
  python3 - "$source/assets/scenes/example.json" "$1.json" "$2" "$3" "$4" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["renderer"].update({"deferred": sys.argv[3] == "on", "ssao": sys.argv[4] == "on", "debug_view": sys.argv[5]})
scene["ambient"] = [0.6, 0.6, 0.6]   # ambient occlusion darkens the ambient light: make it count
json.dump(scene, open(sys.argv[2], "w"), indent=2)
PY
  "$program" "$1.json" --render "$1.png" > "$1.log" 2>&1 || { cat "$1.log"; fail "stoa-editor could not render $1"; }
}
scene forward off off final
scene deferred on off final
scene occlusion on on final
scene normals on off normals

read -r x y <<< "$(python3 "$here/editor_check.py" pixel forward.json 512 512 3 0 4)"
read -r r g b <<< "$(python3 "$here/editor_check.py" colour normals.png "$x" "$y")"
[ "$g" -gt "$r" ] && [ "$g" -gt "$b" ] || fail "the normals view at the floor ($x, $y) is ($r, $g, $b): green should be the strongest"
read -r fr fg fb <<< "$(python3 "$here/editor_check.py" colour forward.png "$x" "$y")"
read -r dr dg db <<< "$(python3 "$here/editor_check.py" colour deferred.png "$x" "$y")"
[ $((dr + dg + db)) -gt 60 ] || fail "the deferred picture's floor ($x, $y) is dark: ($dr, $dg, $db) (forward: $fr, $fg, $fb)"

# In front of the column's foot, where the floor meets the column: ambient
# occlusion darkens the floor there.
read -r cx cy <<< "$(python3 - deferred.json <<'PY'
import json, sys
column = next(o for o in json.load(open(sys.argv[1]))["objects"] if o["name"] == "column")
x, y, z = column["position"]
print(x, z + 0.55)
PY
)"
read -r x y <<< "$(python3 "$here/editor_check.py" pixel deferred.json 512 512 "$cx" 0 "$cy")"
read -r dr dg db <<< "$(python3 "$here/editor_check.py" colour deferred.png "$x" "$y")"
read -r or og ob <<< "$(python3 "$here/editor_check.py" colour occlusion.png "$x" "$y")"
echo "the floor at the column's foot ($x, $y): deferred ($dr, $dg, $db), with ambient occlusion ($or, $og, $ob)"
[ $((or + og + ob)) -lt $((dr + dg + db - 15)) ] || fail "ambient occlusion did not darken the floor at the column's foot"
echo "forward, deferred, occlusion and normals drawn; floor normal ($r, $g, $b)"
