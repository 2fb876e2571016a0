#!/usr/bin/env bash
# stoa-grade-class on up to four synthetic submissions made from this tree. A
# "finished" labs/ tree is what a student writes: the stubs with the solutions'
# code pasted in, their includes and layout kept (make_submission.py):
#   alice/         a folder: the finished labs/ tree                   -> full marks
#   bob.zip        the stubs, inside one top folder (bob-main/labs/)    -> 0, every lab "not attempted"
#   carol.tar.gz   finished, with a compile error in the first lab      -> that lab (and the labs
#                  using its code) "does not compile"; the batch goes on
#   dave/          finished, with a planted mistake in the first lab that a later lab
#                  uses: that lab fails, but the later lab gets full marks from its
#                  cascade run (graded with the earlier lab's solution; Cascade.hpp).
#                  In the layout of releases before the student/ folders (his files
#                  at labs/NN_name/FILE), which the grader still accepts.
# Then checks the gradebook rows, each student's results.json, and that class.json
# says what the gradebook says.
#
#   [STOA_GRADE_CLASS_STUDENTS="alice dave"] [STOA_GRADE_CLASS_LABS="04_normal_mapping"] \
#     grade_class.sh <stoa-grade-class> <stoa-grade> <source dir> <work dir>
#
# STOA_GRADE_CLASS_STUDENTS limits the submissions to some of alice, bob, carol
# and dave (default: all four); the checks are those of the students graded.
# STOA_GRADE_CLASS_LABS grades only those labs (--lab; default: every lab), as the
# sanitizer build does with its one lab (a Debug ASan build grades a lab in about
# a minute, all eleven in nine).
set -euo pipefail
grade_class=$1 grade=$2 source=$3 work=$4
students=${STOA_GRADE_CLASS_STUDENTS:-alice bob carol dave}
for student in $students; do
  case "$student" in
    alice|bob|carol|dave) ;;
    *) echo "grade_class.sh: STOA_GRADE_CLASS_STUDENTS names '$student'; expected some of: alice bob carol dave" >&2
       exit 2 ;;
  esac
done
[ -n "${students// /}" ] || { echo "grade_class.sh: STOA_GRADE_CLASS_STUDENTS is empty; name some of: alice bob carol dave" >&2; exit 2; }
wanted() { case " $students " in *" $1 "*) return 0 ;; *) return 1 ;; esac; }
make_submission="$(dirname "$0")/make_submission.py"
rm -rf "$work"
mkdir -p "$work/submissions" "$work/make"

if wanted alice; then
  python3 "$make_submission" "$source" "$work/submissions/alice/labs"
fi

if wanted bob; then
  mkdir -p "$work/make/bob/bob-main/labs"
  cp -r "$source"/labs/. "$work/make/bob/bob-main/labs"/
  (cd "$work/make/bob" && zip -q -r "$work/submissions/bob.zip" bob-main)
fi

broken_lab=""
if wanted carol; then
  python3 "$make_submission" "$source" "$work/make/carol/labs"
  broken=$(cd "$work/make/carol/labs" && ls -d [0-9][0-9]_*/student/*.cpp | head -1)
  echo "this is not C++;" >> "$work/make/carol/labs/$broken"
  (cd "$work/make/carol" && tar -czf "$work/submissions/carol.tar.gz" labs)
  broken_lab=${broken%%/*}
  echo "carol's compile error is in $broken"
fi

# dave: the first lab's first planted mistake applied to his finished copy.
dave_lab=$(cd "$source/labs" && grep -l "USES" [0-9][0-9]_*/CMakeLists.txt | head -1 | xargs grep -o "USES [0-9][0-9]_[a-z_]*" | head -1 | cut -d' ' -f2)
dave_user=$(cd "$source/labs" && grep -l "USES" [0-9][0-9]_*/CMakeLists.txt | head -1 | cut -d/ -f1)
if wanted dave; then
  python3 "$make_submission" "$source" "$work/submissions/dave/labs"
  python3 - "$source" "$work/submissions/dave/labs" "$dave_lab" <<'PY'
import glob, os, re, sys
source, labs, lab = sys.argv[1:4]
mistake = sorted(glob.glob(os.path.join(source, "solutions", lab, "mistakes", "*.mistake")))[0]
text = open(mistake).read()
name = re.search(r"^file:\s*(\S+)", text, re.M).group(1)
find = text.split("--- find\n", 1)[1].split("--- replace\n", 1)[0]
replace = text.split("--- replace\n", 1)[1].split("--- end", 1)[0]
path = os.path.join(labs, lab, "student", name)
code = open(path).read()
assert code.count(find) == 1, f"{mistake}: the find text is not in {path} once"
open(path, "w").write(code.replace(find, replace))
print(f"dave's {lab} has the mistake {os.path.basename(mistake)}")
PY
  # The layout of older releases: each lab's student files beside its app.
  for folder in "$work/submissions/dave/labs"/[0-9][0-9]_*/student; do
    find "$folder" -maxdepth 1 -type f ! -name 'lab[0-9][0-9].hpp' -exec mv {} "$folder/.." \;
    rm -rf "$folder"
  done
fi

lab_options=()
for lab in ${STOA_GRADE_CLASS_LABS:-}; do
  lab_options+=(--lab "$lab")
done
"$grade_class" "$work/submissions" --out "$work/out" --jobs 2 "${lab_options[@]}"

# The class report says what the gradebook says (check_class_report.py, e2e.class_report).
python3 - "$(dirname "$0")" "$work/out" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import check_class_report as report
report.check_against_gradebook(sys.argv[2])
for message in report.failures:
    print("FAIL: class.json:", message)
sys.exit(1 if report.failures else 0)
PY

python3 - "$work/out" "$broken_lab" "$("$grade" --help | grep -c -- --html || true)" "$dave_lab" "$dave_user" \
          "$students" <<'PY'
import csv, json, os, sys
out, broken_lab, has_html = sys.argv[1], sys.argv[2], sys.argv[3] != "0"
dave_lab, dave_user, students = sys.argv[4], sys.argv[5], sorted(sys.argv[6].split())
rows = {row["student"]: row for row in csv.DictReader(open(os.path.join(out, "gradebook.csv")))}
failures = []
def check(condition, message):
    if not condition:
        failures.append(message)
def results_of(student):
    return json.load(open(os.path.join(out, student, "results.json")))
def lab_max(results, lab):
    # The lab's counted points: its cases, or its build test when it did not compile.
    return sum(t["max_score"] for t in results["tests"] if t["name"].startswith(lab + "/"))
check(sorted(rows) == students, f"students in the gradebook: {sorted(rows)}, expected {students}")
labs = [c for c in next(csv.reader(open(os.path.join(out, "gradebook.csv"))))[1:] if c[:2].isdigit()]
check(len(labs) >= 1, "no lab columns")
if len(set(rows[s]["max"] for s in rows)) > 1:
    failures.append(f"the students' max differ: {[(s, rows[s]['max']) for s in rows]}")
for student in rows:
    check(float(rows[student]["max"]) > 0, f"{student}: max is 0")
if "alice" in rows:
    # The stubs with the solutions' code pasted in: every lab compiles and gets full marks.
    alice = rows["alice"]
    check(alice["total"] == alice["max"] and alice["status"] == "graded", f"alice: {alice}")
    alice_results = results_of("alice")
    check(not [t["name"] for t in alice_results["tests"] if t["name"].endswith("/build")],
          f"alice has build tests: {[t['output'][:200] for t in alice_results['tests'] if t['name'].endswith('/build')]}")
    for lab in labs:
        check(float(alice[lab]) == lab_max(alice_results, lab) > 0, f"alice's {lab}: {alice[lab]} of {lab_max(alice_results, lab)}")
    # Alice's lab uses solutions on both runs: the own run counts on the tie.
    check(all("not counted" in t["tags"] for t in alice_results["tests"] if "cascade" in t["tags"]),
          "alice's cascade run should not count (a tie)")
if "bob" in rows:
    bob = rows["bob"]
    check(float(bob["total"]) == 0 and bob["status"] == "graded", f"bob: {bob}")
    for lab in labs:
        check(f"{lab}: not attempted" in bob["notes"], f"bob's {lab} is not 'not attempted': {bob['notes']}")
if "carol" in rows:
    carol = rows["carol"]
    check(float(carol[broken_lab]) == 0, f"carol's {broken_lab}: {carol[broken_lab]}")
    check(carol["status"] in ("build failed", "partly built"), f"carol's status: {carol['status']}")
    check(f"{broken_lab}: does not compile" in carol["notes"] and "error" in carol["notes"], f"carol's notes: {carol['notes']}")
    carol_results = results_of("carol")
    build = [t for t in carol_results["tests"] if t["name"] == f"{broken_lab}/build"]
    check(len(build) == 1 and "error" in build[0]["output"], "carol's results.json has no build test with the compiler error")
    # The text total counts the lab that did not compile.
    score_line = carol_results["output"].splitlines()[0] if carol_results["output"] else ""
    expected = f"score: {float(carol['total']):g} / {float(carol['max']):g}"
    check(score_line.startswith(expected + " ") or score_line == expected,
          f"carol's output starts '{score_line}', expected '{expected} (...)'")
if "dave" in rows:
    # Cascades: dave's mistake costs him in its own lab, not in the lab that uses it.
    dave = rows["dave"]
    dave_results = results_of("dave")
    check(float(dave[dave_lab]) < lab_max(dave_results, dave_lab), f"dave's {dave_lab} should lose points: {dave[dave_lab]}")
    check(float(dave[dave_user]) == lab_max(dave_results, dave_user) > 0,
          f"dave's {dave_user}: {dave[dave_user]}, expected full marks {lab_max(dave_results, dave_user)} from its cascade run")
    own = [t for t in dave_results["tests"] if t["name"].startswith(dave_user + "/") and "cascade" not in t["tags"]]
    cascade = [t for t in dave_results["tests"] if t["name"].startswith(dave_user + "/") and "cascade" in t["tags"]]
    check(len(cascade) > 0 and len(cascade) == len(own), f"dave's {dave_user}: {len(own)} own and {len(cascade)} cascade tests")
    check(any(t["status"] == "failed" for t in own), f"dave's own {dave_user} run should fail a case (the mistake shows through)")
    check(all(t["status"] == "passed" and t["score"] == t["max_score"] > 0 for t in cascade),
          f"dave's cascade run of {dave_user} should pass and count: {[(t['name'], t['status'], t['score']) for t in cascade]}")
    check(all("not counted" in t["tags"] and t["max_score"] == 0 for t in own), "dave's own run should be marked not counted")
for student in rows:
    results = results_of(student)
    total = sum(test["score"] for test in results["tests"])
    check(abs(results["score"] - total) < 1e-9, f"{student}: score {results['score']} != sum of tests {total}")
    check(abs(results["score"] - float(rows[student]["total"])) < 1e-9, f"{student}: results.json and gradebook differ")
    maximum = sum(test["max_score"] for test in results["tests"])
    check(abs(maximum - float(rows[student]["max"])) < 1e-9, f"{student}: results.json's max {maximum} != gradebook's {rows[student]['max']}")
    if has_html and student != "carol":
        check(os.path.isfile(os.path.join(out, student, "report.html")), f"{student}: no report.html")
for message in failures:
    print("FAIL:", message)
print(open(os.path.join(out, "gradebook.csv")).read())
sys.exit(1 if failures else 0)
PY
