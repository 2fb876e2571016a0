#!/bin/sh
# Raw GL in a student's pass is named, not silently wrong: lab 05 with its
# depth pass written with glEnable/glDisable instead of a PassDescription
# (tests/data/variants/05_shadows/raw_gl_shadow_pass.equivalent). Every case
# that draws the shadow map is an error that says "GL state changed outside
# RenderState in renderShadowPass()" and names a state; no case gets a gallery
# hint (the pictures are not a known mistake's).
#   raw_gl_state_named.sh STOA_GRADE PROGRAM_DIR WORK_DIR
set -eu
grade=$1 bin=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
"$grade" --bin-dir "$bin" --lab 05_shadows --jobs 2 --work-dir "$work/run" --json "$work/results.json" \
  >"$work/report.txt" 2>"$work/progress.txt" || true
cat "$work/report.txt"
if grep -q "hint: " "$work/report.txt"; then echo "FAIL: a gallery hint for a pass that set GL state behind RenderState"; exit 1; fi
python3 - "$work/results.json" <<'PY'
import json, sys
tests = json.load(open(sys.argv[1]))["tests"]
named = [t["name"] for t in tests if "GL state changed outside RenderState in renderShadowPass()" in t.get("output", "")
         and ("GL_CULL_FACE" in t["output"] or "GL_DEPTH_TEST" in t["output"])]
passed = [t["name"] for t in tests if t["score"] == t["max_score"]]
print(f"{len(named)} cases name the state changed outside RenderState; {len(passed)} pass")
if len(named) < 10:
    print("FAIL: fewer than 10 of lab 05's cases name the raw GL state")
    sys.exit(1)
PY
