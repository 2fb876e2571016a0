#!/usr/bin/env bash
# The Gradescope package and the Classroom workflow, offline:
#   - make-gradescope-package.sh writes a zip with setup.sh and run_autograder at
#     its root and the student release (no solutions/) in stoa/;
#   - run_autograder, with /autograder moved under the work folder (its paths are
#     overridable) and this build as the framework, grades a submission made as a
#     student makes it (the stubs with the solutions' code pasted in, their includes
#     kept: make_submission.py) and writes a results.json with Gradescope's keys and
#     full marks for every lab;
#   - a second run_autograder, on the same submission with a compile error in one
#     lab, scores that lab 0 and reports the total out of every lab's points, in
#     results.json's score and in the score line of its output;
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

# A second upload, the same with a compile error in one lab that no other lab
# uses: that lab scores 0 and the totals (results.json's score, the score line
# of its output) still count its points in the maximum.
broken_root=$work/autograder-broken
mkdir -p "$broken_root/submission"
python3 "$make_submission" "$source" "$broken_root/submission/labs"
broken=$(python3 - "$source/labs" <<'PY'
import pathlib, re, sys
labs = sorted(p for p in pathlib.Path(sys.argv[1]).iterdir() if (p / "CMakeLists.txt").is_file())
text = {lab.name: (lab / "CMakeLists.txt").read_text() for lab in labs}
used = {name for t in text.values() if "USES" in t for name in re.findall(r"\b\d\d_\w+", t.split("USES", 1)[1])}
for lab in labs:
    files = re.search(r"STUDENT_FILES([^)]*?)(APP_SOURCES|USES|\))", text[lab.name], re.S).group(1).split()
    cpp = [f for f in files if f.endswith(".cpp")]
    if cpp and lab.name not in used:
        print(f"{lab.name}/student/{cpp[0]}")
        break
PY
)
[ -n "$broken" ] || { echo "FAIL: no lab with a C++ student file that no other lab uses, to break"; exit 1; }
echo "this is not C++;" >> "$broken_root/submission/labs/$broken"
echo "the second upload's compile error is in $broken"

# Both graded at once (each builds its labs one compiler at a time).
STOA_AUTOGRADER_ROOT=$root STOA_FRAMEWORK_BUILD=$build "$root/source/run_autograder" > "$work/full.log" 2>&1 &
full_pid=$!
STOA_AUTOGRADER_ROOT=$broken_root STOA_TREE=$root/source/stoa STOA_FRAMEWORK_BUILD=$build \
  "$root/source/run_autograder" > "$work/broken.log" 2>&1 &
broken_pid=$!
full_status=0 broken_status=0
wait "$full_pid" || full_status=$?
wait "$broken_pid" || broken_status=$?
echo "== run_autograder, the finished labs"; cat "$work/full.log"
echo "== run_autograder, $broken broken"; cat "$work/broken.log"
[ "$full_status" = 0 ] && [ "$broken_status" = 0 ] ||
  { echo "FAIL: run_autograder exited with $full_status (finished labs) and $broken_status ($broken broken)"; exit 1; }

python3 - "$root/results/results.json" "$root/source/stoa/autograder/classroom/grade.yml" \
          "$broken_root/results/results.json" "${broken%%/*}" "$source/labs" <<'PY'
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
labs = sorted(p.name for p in pathlib.Path(sys.argv[5]).iterdir() if (p / "cases.ini").is_file())
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

# One lab broken: 0 for it, the rest in full, and the totals out of the same maximum.
broken_results, broken_lab = json.load(open(sys.argv[3])), sys.argv[4]
broken_tests = broken_results.get("tests", [])
lab_maximum = lab_points(tests, broken_lab, "max_score")
expected = maximum - lab_maximum
build = [t for t in broken_tests if t.get("name") == f"{broken_lab}/build"]
if not (len(build) == 1 and build[0].get("max_score") == lab_maximum and build[0].get("status") == "failed"
        and "error" in build[0].get("output", "")):
    failures.append(f"{broken_lab} broken: no failed {broken_lab}/build test worth {points(lab_maximum)} "
                    f"with the compiler's error: {build}")
if abs(broken_results.get("score", -1) - expected) > 1e-9:
    failures.append(f"{broken_lab} broken: score {broken_results.get('score')}, expected {points(expected)}")
broken_maximum = sum(test.get("max_score", 0) for test in broken_tests)
if abs(broken_maximum - maximum) > 1e-9:
    failures.append(f"{broken_lab} broken: the tests are worth {points(broken_maximum)}, expected {points(maximum)}")
if not score_line(broken_results).startswith(f"score: {points(expected)} / {points(maximum)} ("):
    failures.append(f"{broken_lab} broken: the output starts '{score_line(broken_results)}', "
                    f"expected 'score: {points(expected)} / {points(maximum)} (...)'")
print(f"{broken_lab} broken: {score_line(broken_results)}")
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
