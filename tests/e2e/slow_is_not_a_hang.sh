#!/bin/sh
# Slow is not a hang: lab 07 with a BVH that never splits (it finds the right
# hits, far too slowly; tests/data/variants/07_picking/bvh_never_splits.equivalent)
# loses its ray-cast cases as "too slow", pointed to the page's "How fast"
# section, and the checks of the tree's splits and leaves (bvh_cheapest_split,
# bvh_structure) as "does not hold"; every other case is graded and passes.
#   slow_is_not_a_hang.sh STOA_GRADE PROGRAM_DIR WORK_DIR
set -eu
grade=$1 bin=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
status=0
"$grade" --bin-dir "$bin" --lab 07_picking --jobs 2 --work-dir "$work/run" --json "$work/results.json" \
  >"$work/report.txt" 2>"$work/progress.txt" || status=$?
cat "$work/report.txt"
python3 - "$work/results.json" <<'PY'
import json, sys
tests = json.load(open(sys.argv[1]))["tests"]
slow, problems = [], []
for test in tests:
    name, output = test["name"], test.get("output", "")
    passed = test["score"] == test["max_score"]
    if "raycast" in name:
        if passed:
            continue   # a fast machine may finish one
        slow.append(name)
        if "too slow: still computing" not in output or '"How fast"' not in output:
            problems.append(f"{name}: not reported as too slow with the 'How fast' pointer: {output!r}")
    elif name.endswith("/bvh_cheapest_split") or name.endswith("/bvh_structure"):
        if passed or "does not hold" not in output:
            problems.append(f"{name}: a tree that never splits should fail the split check: {output!r}")
    elif not passed:
        problems.append(f"{name}: lost, though only the ray casts are slow: {output!r}")
if not slow:
    problems.append("no ray-cast case ran past its limit: the variant is not slow")
for problem in problems:
    print("FAIL:", problem)
print(f"{len(slow)} ray-cast cases too slow; {len(tests) - len(slow)} other cases graded")
sys.exit(1 if problems else 0)
PY
