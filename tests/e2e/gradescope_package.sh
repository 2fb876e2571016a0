#!/usr/bin/env bash
# The Gradescope package and the Classroom workflow, offline:
#   - make-gradescope-package.sh writes a zip with setup.sh and run_autograder at
#     its root and the student release (no solutions/) in stoa/;
#   - run_autograder, with /autograder moved under the work folder (its paths are
#     overridable) and this build as the framework, grades a submission holding the
#     solutions and writes a results.json with Gradescope's keys and full marks;
#   - the Classroom workflow parses as YAML (where python3 has yaml).
#
#   gradescope_package.sh <source dir> <framework build dir> <work dir>
set -euo pipefail
source=$1 build=$2 work=$3
rm -rf "$work"
mkdir -p "$work"

"$source/autograder/make-gradescope-package.sh" "$work/autograder.zip"
root=$work/autograder
mkdir -p "$root/source" "$root/submission"
(cd "$root/source" && unzip -q "$work/autograder.zip")
for file in setup.sh run_autograder; do
  [ -x "$root/source/$file" ] || { echo "FAIL: the package has no executable $file at its root"; exit 1; }
  bash -n "$root/source/$file"
done
[ -f "$root/source/stoa/CMakeLists.txt" ] || { echo "FAIL: the package has no stoa/ tree"; exit 1; }
[ ! -e "$root/source/stoa/solutions" ] || { echo "FAIL: the package holds solutions/ without --with-hidden"; exit 1; }

# The student's upload: a repository whose labs/ hold the solutions.
cp -r "$source/labs" "$root/submission/labs"
for lab in "$source"/solutions/[0-9][0-9]_*/; do
  name=$(basename "$lab")
  for file in "$lab"*; do
    if [ -f "$file" ] && [ -f "$root/submission/labs/$name/$(basename "$file")" ]; then
      cp "$file" "$root/submission/labs/$name/"
    fi
  done
done

STOA_AUTOGRADER_ROOT=$root STOA_FRAMEWORK_BUILD=$build "$root/source/run_autograder"

python3 - "$root/results/results.json" "$root/source/stoa/autograder/classroom/grade.yml" <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))
failures = []
for key in ("score", "tests", "output"):
    if key not in results:
        failures.append(f"results.json has no '{key}'")
tests = results.get("tests", [])
if not tests:
    failures.append("results.json has no tests")
for test in tests:
    for key in ("score", "max_score", "status", "name", "output", "visibility"):
        if key not in test:
            failures.append(f"test {test.get('name')} has no '{key}'")
    if test.get("status") not in ("passed", "failed"):
        failures.append(f"test {test.get('name')}: status {test.get('status')}")
maximum = sum(test.get("max_score", 0) for test in tests)
if not (maximum > 0 and abs(results.get("score", -1) - maximum) < 1e-9):
    failures.append(f"the solutions scored {results.get('score')} of {maximum}")
try:
    import yaml
except ImportError:
    print("note: python3 has no yaml; the Classroom workflow is not parsed")
else:
    workflow = yaml.safe_load(open(sys.argv[2]))
    steps = workflow["jobs"]["grade"]["steps"]
    if not any("stoa-grade" in step.get("run", "") for step in steps):
        failures.append("the Classroom workflow runs no stoa-grade")
    if not any(step.get("uses", "").startswith("actions/upload-artifact") for step in steps):
        failures.append("the Classroom workflow uploads no report")
for failure in failures:
    print("FAIL:", failure)
print(f"results.json: score {results.get('score')} of {maximum}, {len(tests)} tests")
sys.exit(1 if failures else 0)
PY
