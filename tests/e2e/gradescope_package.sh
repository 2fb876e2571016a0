#!/usr/bin/env bash
# The Gradescope package and the Classroom workflow, offline:
#   - make-gradescope-package.sh writes a zip with setup.sh and run_autograder at
#     its root and the student release (no solutions/) in stoa/;
#   - run_autograder, with /autograder moved under the work folder (its paths are
#     overridable) and this build as the framework, grades a submission made as a
#     student makes it (the stubs with the solutions' code pasted in, their includes
#     kept: make_submission.py) and writes a results.json with Gradescope's keys and
#     full marks for every lab;
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

# The student's upload: a repository whose labs/ are the stubs with the solutions'
# code pasted in, their includes and layout kept (what a student who finished
# every lab has).
make_submission="$(cd "$(dirname "$0")" && pwd)/make_submission.py"
python3 "$make_submission" "$source" "$root/submission/labs"

# A compile error in one lab (0 for it, its build test with the compiler's error,
# the total still out of every lab's points, in results.json and the score line)
# is e2e.grade_class's carol: the same stoa-grade-class writes the same results.json.
# A second upload here graded the whole course again for it, 9 minutes of CI.
STOA_AUTOGRADER_ROOT=$root STOA_FRAMEWORK_BUILD=$build "$root/source/run_autograder" > "$work/full.log" 2>&1 ||
  { status=$?; cat "$work/full.log"; echo "FAIL: run_autograder exited with $status"; exit 1; }
echo "== run_autograder, the finished labs"; cat "$work/full.log"

python3 - "$root/results/results.json" "$root/source/stoa/autograder/classroom/grade.yml" "$source/labs" <<'PY'
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
    failures.append(f"the finished labs scored {results.get('score')} of {maximum}")
def lab_points(tests, lab, key):
    return sum(test.get(key, 0) for test in tests if test.get("name", "").startswith(lab + "/"))
def score_line(results):
    output = results.get("output", "")
    return output.splitlines()[0] if output else ""
def points(value):
    return f"{value:g}"
# Every lab graded at full marks: none left out, none failing to compile.
import pathlib
labs = sorted(p.name for p in pathlib.Path(sys.argv[3]).iterdir() if (p / "cases.ini").is_file())
for lab in labs:
    if not lab_points(tests, lab, "max_score") > 0:
        failures.append(f"the finished labs: {lab} has no counted test")
    elif lab_points(tests, lab, "score") != lab_points(tests, lab, "max_score"):
        failures.append(f"the finished labs: {lab} scored {lab_points(tests, lab, 'score')} of "
                        f"{lab_points(tests, lab, 'max_score')}")
for test in tests:
    if test.get("name", "").endswith("/build"):
        failures.append(f"the finished labs: {test['name']}: {test.get('output', '')[:300]}")
if not score_line(results).startswith(f"score: {points(maximum)} / {points(maximum)} ("):
    failures.append(f"the finished labs' output starts '{score_line(results)}', expected 'score: {points(maximum)} / {points(maximum)} (...)'")

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
