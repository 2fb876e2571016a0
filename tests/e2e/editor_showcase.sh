#!/usr/bin/env bash
# editor_showcase.sh STOA_EDITOR SOURCE_DIR WORK_DIR BACKEND [views]
# The showcase (stoa-editor --scene showcase) drawn headless on BACKEND (osmesa
# or egl) at 480x270, with every lab's pass on: the log names no missing lab
# function; the sky's band is bright; the ground holds the point lights'
# coloured pools; under a bright sun, switching the shadows off brightens the
# picture (shadows keep half the sunlight: lab 05's umbra). With
# `views`, each debug view of the renderer panel is drawn too and differs
# from the final picture.
set -euo pipefail
program=$1 source=$2 work=$3 backend=$4 views=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
checker() { python3 "$here/editor_check.py" "$@"; }
fail() { echo "FAIL: $*"; exit 1; }
mkdir -p "$work"
cd "$work"

render() {   # NAME [KEY=VALUE of the renderer settings...]: the showcase so changed, drawn to NAME.png
  local name=$1; shift
  python3 - "$source/assets/scenes/showcase.json" "$name.json" "$@" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
for setting in sys.argv[3:]:
    key, value = setting.split("=")
    if key == "sun":   # the sun's colour, grey
        scene["sun"]["color"] = [float(value)] * 3
    else:
        scene["renderer"][key] = {"true": True, "false": False}.get(value, value)
json.dump(scene, open(sys.argv[2], "w"), indent=2)
PY
  "$program" "$name.json" --size 480x270 --render "$name.png" --backend "$backend" > "$name.log" 2>&1 ||
    { cat "$name.log"; fail "stoa-editor could not draw $name"; }
  if grep -E "needs|cannot|normal maps off" "$name.log"; then fail "$name: a pass is missing (the log above)"; fi
}

render final
checker showcase final.png || fail "the headless picture does not look like the showcase (above)"
render shadowed sun=1.5
render unshadowed sun=1.5 shadows=false
read -r ur ug ub coloured <<< "$(checker band unshadowed.png 0.3 1)"
read -r sr sg sb coloured <<< "$(checker band shadowed.png 0.3 1)"
echo "lower picture under a bright sun with shadows ($sr, $sg, $sb), without ($ur, $ug, $ub)"
[ $((ur + ug + ub)) -gt $((sr + sg + sb + 15)) ] || fail "switching the shadows off did not brighten the picture"

if [ "$views" = views ]; then
  for view in albedo normals positions specular tiles occlusion cascades lod trails ids; do
    render "$view" debug_view="$view"
    percent=$(checker differ final.png "$view.png")
    echo "view $view differs from the final picture in $percent % of its pixels"
    least=5
    [ "$view" = lod ] && least=2      # only the objects' colours change, not the ground or the sky
    [ "$view" = trails ] && least=0.3 # thin lines over the final picture
    awk "BEGIN { exit !($percent >= $least) }" || fail "the $view view looks like the final picture"
  done
fi
echo "the showcase drawn on $backend"
