#!/usr/bin/env bash
# docs/generate-showcase-images.sh [BUILD_DIR]
# Renders the pictures of docs/showcase.md from a solutions build (default
# build-solutions) into docs/images/showcase/: at 640x360 the showcase's frame, each debug view of the renderer panel, and the frame
# with one pass switched off at a time; and, where Xvfb and xdotool are
# installed, the editor's window with its panels (stoa-editor --scene showcase,
# F12 once the crowd has walked a few seconds).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-solutions}
editor="$build/bin/stoa-editor"
[ -x "$editor" ] || { echo "generate-showcase-images: no $editor; build with -DSTOA_USE_SOLUTIONS=ON first" >&2; exit 1; }
out="$root/docs/images/showcase"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# variant NAME SIZE [KEY=VALUE...]: the showcase with those renderer settings, drawn to NAME.png
variant() {
  local name=$1 size=$2; shift 2
  python3 - "$root/assets/scenes/showcase.json" "$work/$name.json" "$@" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
for setting in sys.argv[3:]:
    key, value = setting.split("=")
    scene["renderer"][key] = {"true": True, "false": False}.get(value, value)
json.dump(scene, open(sys.argv[2], "w"), indent=2)
PY
  echo "generate-showcase-images: $name"
  "$editor" "$work/$name.json" --size "$size" --render "$out/$name.png" > "$work/$name.log" 2>&1 ||
    { cat "$work/$name.log" >&2; exit 1; }
}

variant final 640x360
for view in albedo normals tiles occlusion cascades lod trails ids; do variant "view-$view" 640x360 debug_view="$view"; done
variant without-shadows 640x360 shadows=false
variant without-normal-maps 640x360 normal_maps=false
variant without-occlusion 640x360 ssao=false
variant without-sky 640x360 sky=false
variant without-culling 640x360 culling=false

if command -v Xvfb > /dev/null && command -v xdotool > /dev/null; then
  echo "generate-showcase-images: the window (Xvfb)"
  cat > "$work/window.sh" <<'SH'
#!/usr/bin/env bash
set -euo pipefail
editor=$1 picture=$2
"$editor" --scene showcase --size 1280x720 > window.log 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT
for _ in $(seq 1 200); do
  window=$(xdotool search --onlyvisible --name "Stoa lab" 2>/dev/null | head -n 1 || true)
  [ -n "$window" ] && break
  sleep 0.1
done
[ -n "$window" ] || { echo "no window"; exit 1; }
xdotool windowfocus --sync "$window"
sleep 4   # the crowd walks, the lights wander
xdotool key F12
for _ in $(seq 1 200); do
  grep -q "^saved lab11_editor-screenshot.png$" window.log && break
  sleep 0.1
done
mv lab11_editor-screenshot.png "$picture"
SH
  (cd "$work" && "$root/tests/e2e/run_in_xvfb.sh" bash "$work/window.sh" "$editor" "$out/window.png") ||
    { cat "$work/window.log" >&2; exit 1; }
else
  echo "generate-showcase-images: no Xvfb or xdotool: docs/images/showcase/window.png left as it is"
fi
