#!/usr/bin/env bash
# editor_crowd_reload.sh STOA_EDITOR WORK_DIR
# stoa-editor in a window under Xvfb on a scene drawn by the deferred pipeline
# whose crowd world, world.xml, lies beside the scene file (a copy of the Mars
# explorers, with the files it names). The world saved with fewer robots (written elsewhere and renamed
# over it, as editors save) must start the crowd again ("crowd: world.xml
# changed"), and a broken save must keep the crowd that walks, with the file
# and line of the error in the log.
set -euo pipefail
program=$1 work=$2
source_dir=$(cd "$(dirname "$0")/../.." && pwd)

source "$(dirname "$0")/window_common.sh"   # Xvfb, fail, start_lab_window, wait_for_output
source "$(dirname "$0")/editor_common.sh"   # checker, screenshot

cd "$work"
rm -f ./*.png ./*.xml ./*.md2 scene.json
cp "$source_dir"/assets/crowds/* .   # the world's includes, maps and models are found beside it
cp mars_explorers.xml world.xml
cat > scene.json <<'JSON'
{
  "stoa_scene": 2,
  "ambient": [0.3, 0.3, 0.3],
  "camera": { "target": [0, 0, 0], "distance": 30, "yaw": 0, "pitch": 50 },
  "renderer": { "deferred": true, "ssao": false, "sky": false },
  "crowd_world": "world.xml",
  "materials": [ { "name": "ground", "diffuse": [0.5, 0.5, 0.5] } ],
  "objects": [ { "id": 1, "name": "floor", "mesh": "shape:plane", "material": "ground", "scale": [30, 1, 30] } ]
}
JSON

start_lab_window scene.json --size 320x240
screenshot first-frame.png
sed 's/count="20"/count="5"/' world.xml > world.xml.new
mv world.xml.new world.xml
wait_for_output -F "crowd: world.xml changed, the crowd starts again" "saving world.xml did not start the crowd again"
sed 's/<base /<base x= /' world.xml > world.xml.new   # an attribute twice: not XML
mv world.xml.new world.xml
wait_for_output "cannot reload .*world.xml" "a broken world.xml was not reported"
grep -E "cannot reload .*world.xml.*:[0-9]+" "$work/stdout.txt" || fail "the broken world.xml's error does not name its line"
quit_with_escape
echo "world.xml reloaded, and a broken save kept the crowd"
