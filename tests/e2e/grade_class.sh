#!/usr/bin/env bash
# stoa-grade-class on three synthetic submissions made from this tree:
#   alice/         a folder: the solutions copied into a labs/ tree     -> full marks
#   bob.zip        the stubs, inside one top folder (bob-main/labs/)    -> 0, every lab "not attempted"
#   carol.tar.gz   the solutions with a compile error in the first lab  -> that lab (and the labs
#                  using its code) "does not compile"; the batch goes on
#   dave/          the solutions with a planted mistake in the first lab that a later lab
#                  uses: that lab fails, but the later lab gets full marks from its
#                  cascade run (graded with the earlier lab's solution; Cascade.hpp)
# Then checks the gradebook rows and each student's results.json.
#
#   grade_class.sh <stoa-grade-class> <stoa-grade> <source dir> <work dir>
set -euo pipefail
grade_class=$1 grade=$2 source=$3 work=$4
rm -rf "$work"
mkdir -p "$work/submissions" "$work/make"

# A labs/ tree: the student's copy of labs/, with the solutions' twins over it when asked.
make_labs() {
  local dest=$1 kind=$2
  mkdir -p "$dest"
  cp -r "$source"/labs/. "$dest"/
  if [ "$kind" = solutions ]; then
    for lab in "$source"/solutions/[0-9][0-9]_*/; do
      name=$(basename "$lab")
      for file in "$lab"*; do
        if [ -f "$file" ] && [ -f "$dest/$name/$(basename "$file")" ]; then cp "$file" "$dest/$name/"; fi
      done
    done
  fi
}

make_labs "$work/submissions/alice/labs" solutions

make_labs "$work/make/bob/bob-main/labs" stubs
(cd "$work/make/bob" && zip -q -r "$work/submissions/bob.zip" bob-main)

make_labs "$work/make/carol/labs" solutions
broken=$(cd "$work/make/carol/labs" && ls -d [0-9][0-9]_*/*.cpp | grep -v '/lab.cpp$' | head -1)
echo "this is not C++;" >> "$work/make/carol/labs/$broken"
(cd "$work/make/carol" && tar -czf "$work/submissions/carol.tar.gz" labs)
broken_lab=${broken%%/*}
echo "carol's compile error is in $broken"

# dave: the first lab's first planted mistake applied to his copy of the solution.
make_labs "$work/submissions/dave/labs" solutions
dave_lab=$(cd "$source/labs" && grep -l "USES" [0-9][0-9]_*/CMakeLists.txt | head -1 | xargs grep -o "USES [0-9][0-9]_[a-z_]*" | head -1 | cut -d' ' -f2)
dave_user=$(cd "$source/labs" && grep -l "USES" [0-9][0-9]_*/CMakeLists.txt | head -1 | cut -d/ -f1)
python3 - "$source" "$work/submissions/dave/labs" "$dave_lab" <<'PY'
import glob, os, re, sys
source, labs, lab = sys.argv[1:4]
mistake = sorted(glob.glob(os.path.join(source, "solutions", lab, "mistakes", "*.mistake")))[0]
text = open(mistake).read()
name = re.search(r"^file:\s*(\S+)", text, re.M).group(1)
find = text.split("--- find\n", 1)[1].split("--- replace\n", 1)[0]
replace = text.split("--- replace\n", 1)[1].split("--- end", 1)[0]
path = os.path.join(labs, lab, name)
code = open(path).read()
assert code.count(find) == 1, f"{mistake}: the find text is not in {path} once"
open(path, "w").write(code.replace(find, replace))
print(f"dave's {lab} has the mistake {os.path.basename(mistake)}")
PY

"$grade_class" "$work/submissions" --out "$work/out" --jobs 2

python3 - "$work/out" "$broken_lab" "$("$grade" --help | grep -c -- --html || true)" "$dave_lab" "$dave_user" <<'PY'
import csv, json, os, sys
out, broken_lab, has_html = sys.argv[1], sys.argv[2], sys.argv[3] != "0"
dave_lab, dave_user = sys.argv[4], sys.argv[5]
rows = {row["student"]: row for row in csv.DictReader(open(os.path.join(out, "gradebook.csv")))}
failures = []
def check(condition, message):
    if not condition:
        failures.append(message)
check(sorted(rows) == ["alice", "bob", "carol", "dave"], f"students in the gradebook: {sorted(rows)}")
labs = [c for c in next(csv.reader(open(os.path.join(out, "gradebook.csv"))))[1:] if c[:2].isdigit()]
check(len(labs) >= 1, "no lab columns")
alice, bob, carol = rows["alice"], rows["bob"], rows["carol"]
check(float(alice["max"]) > 0, "max is 0")
check(alice["total"] == alice["max"] and alice["status"] == "graded", f"alice: {alice}")
check(float(bob["total"]) == 0 and bob["status"] == "graded", f"bob: {bob}")
for lab in labs:
    check(f"{lab}: not attempted" in bob["notes"], f"bob's {lab} is not 'not attempted': {bob['notes']}")
check(float(carol[broken_lab]) == 0, f"carol's {broken_lab}: {carol[broken_lab]}")
check(carol["status"] in ("build failed", "partly built"), f"carol's status: {carol['status']}")
check(f"{broken_lab}: does not compile" in carol["notes"] and "error" in carol["notes"], f"carol's notes: {carol['notes']}")
check(alice["max"] == bob["max"] == carol["max"] == rows["dave"]["max"], "the students' max differ")
# Cascades: dave's mistake costs him in its own lab, not in the lab that uses it.
dave = rows["dave"]
check(float(dave[dave_lab]) < float(alice[dave_lab]), f"dave's {dave_lab} should lose points: {dave[dave_lab]}")
check(dave[dave_user] == alice[dave_user], f"dave's {dave_user}: {dave[dave_user]}, expected {alice[dave_user]} from its cascade run")
dave_results = json.load(open(os.path.join(out, "dave", "results.json")))
own = [t for t in dave_results["tests"] if t["name"].startswith(dave_user + "/") and "cascade" not in t["tags"]]
cascade = [t for t in dave_results["tests"] if t["name"].startswith(dave_user + "/") and "cascade" in t["tags"]]
check(len(cascade) > 0 and len(cascade) == len(own), f"dave's {dave_user}: {len(own)} own and {len(cascade)} cascade tests")
check(any(t["status"] == "failed" for t in own), f"dave's own {dave_user} run should fail a case (the mistake shows through)")
check(all(t["status"] == "passed" and t["score"] == t["max_score"] > 0 for t in cascade),
      f"dave's cascade run of {dave_user} should pass and count: {[(t['name'], t['status'], t['score']) for t in cascade]}")
check(all("not counted" in t["tags"] and t["max_score"] == 0 for t in own), "dave's own run should be marked not counted")
# Alice's lab uses solutions on both runs: the own run counts on the tie.
alice_results = json.load(open(os.path.join(out, "alice", "results.json")))
check(all("not counted" in t["tags"] for t in alice_results["tests"] if "cascade" in t["tags"]),
      "alice's cascade run should not count (a tie)")
for student in rows:
    results = json.load(open(os.path.join(out, student, "results.json")))
    total = sum(test["score"] for test in results["tests"])
    check(abs(results["score"] - total) < 1e-9, f"{student}: score {results['score']} != sum of tests {total}")
    check(abs(results["score"] - float(rows[student]["total"])) < 1e-9, f"{student}: results.json and gradebook differ")
    if has_html and student != "carol":
        check(os.path.isfile(os.path.join(out, student, "report.html")), f"{student}: no report.html")
carol_results = json.load(open(os.path.join(out, "carol", "results.json")))
build = [t for t in carol_results["tests"] if t["name"] == f"{broken_lab}/build"]
check(len(build) == 1 and "error" in build[0]["output"], "carol's results.json has no build test with the compiler error")
for message in failures:
    print("FAIL:", message)
print(open(os.path.join(out, "gradebook.csv")).read())
sys.exit(1 if failures else 0)
PY
