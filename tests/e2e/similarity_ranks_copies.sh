#!/usr/bin/env bash
# stoa-grade-class --similarity-only ranks copied submissions first, and given
# code never counts. Two classes, nothing built or graded:
#
#   the made-up course in similarity_course/ (through STOA_SOURCE_DIR): ann, ben
#   and cid solved its two labs on their own (C++ and GLSL for sim_c, notes in
#   plain text for sim_text); dora is ann's work with every local name renamed
#   and the functions in the reverse order (her notes reflowed); ed is ben's,
#   reformatted. In each lab the pairs ann-dora and ben-ed must be the first
#   two, above every independent pair. (The course is made up so that the
#   independent solutions give nothing away in the student release.)
#
#   this tree's first lab, where solutions/ exists: alice (the solution pasted
#   into the stubs, make_submission.py), frank (alice's, renamed and reordered),
#   and bob and bea, who handed in the stubs: alice-frank first, bob and bea
#   left out (no code of their own: the stubs' given code does not count).
#
#   similarity_ranks_copies.sh <stoa-grade-class> <source dir> <work dir>
set -euo pipefail
grade_class=$1 source=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
course=$here/similarity_course
command -v sim_c >/dev/null || { echo "similarity_ranks_copies.sh: sim_c is not installed (apt-get install similarity-tester)"; exit 77; }
rm -rf "$work"
mkdir -p "$work/course"

# The made-up course: three independent students and two disguised copies.
for student in ann ben cid; do cp -r "$course/students/$student" "$work/course/"; done
mkdir -p "$work/course/dora/01_words" "$work/course/ed/01_words"
for file in words.cpp tone.glsl; do
  python3 "$here/disguise_copy.py" rename-reorder "$course/students/ann/01_words/$file" \
      "$work/course/dora/01_words/$file" "$course/labs/01_words/student/$file"
  python3 "$here/disguise_copy.py" reformat "$course/students/ben/01_words/$file" \
      "$work/course/ed/01_words/$file" "$course/labs/01_words/student/$file"
done
# The notes (sim_text): dora's are ann's, reflowed to other lines; ed's are ben's, reflowed too.
mkdir -p "$work/course/dora/02_notes" "$work/course/ed/02_notes"
fmt -w 60 "$course/students/ann/02_notes/notes.txt" > "$work/course/dora/02_notes/notes.txt"
fmt -w 120 "$course/students/ben/02_notes/notes.txt" > "$work/course/ed/02_notes/notes.txt"
STOA_SOURCE_DIR=$course "$grade_class" "$work/course" --out "$work/course-out" --similarity-only
# Without SIM on the PATH: exit status 1 and the line saying what to install.
set +e
PATH=/nonexistent STOA_SOURCE_DIR=$course "$grade_class" "$work/course" --out "$work/no-sim" --similarity-only \
    > /dev/null 2> "$work/no-sim.err"
no_sim_status=$?
set -e

# This tree's first lab.
lab=$(cd "$source/labs" && ls -d [0-9][0-9]_* | head -1)
if [ -d "$source/solutions" ]; then
  mkdir -p "$work/tree/bob" "$work/tree/bea"
  python3 "$here/make_submission.py" "$source" "$work/tree/alice/labs" >/dev/null
  cp -r "$work/tree/alice" "$work/tree/frank"
  for file in "$work/tree/frank/labs/$lab/student"/*.cpp; do
    python3 "$here/disguise_copy.py" rename-reorder "$file" "$file" "$source/labs/$lab/student/$(basename "$file")"
  done
  cp -r "$source/labs" "$work/tree/bob/" && cp -r "$source/labs" "$work/tree/bea/"
  "$grade_class" "$work/tree" --out "$work/tree-out" --similarity-only --lab "$lab"
fi

python3 - "$work" "$lab" "$no_sim_status" <<'PY'
import json, os, sys
work, lab, no_sim_status = sys.argv[1], sys.argv[2], int(sys.argv[3])
failures = []
def check(condition, message):
    if not condition:
        failures.append(message)
no_sim = open(os.path.join(work, "no-sim.err")).read()
check(no_sim_status == 1 and "apt-get install similarity-tester" in no_sim,
      f"without SIM: status {no_sim_status}, {no_sim!r}")
def ranking(out, lab_name):
    report = json.load(open(os.path.join(out, "similarity.json")))
    found = [entry for entry in report["labs"] if entry["lab"] == lab_name]
    check(len(found) == 1 and "error" not in found[0], f"{out}: {lab_name} was not compared: {found}")
    entry = found[0] if found else {"pairs": [], "left_out": []}
    print(f"{lab_name}, {entry.get('pairs_compared')} pairs compared:")
    for rank, pair in enumerate(entry["pairs"], 1):
        print(f"  {rank}. {pair['a']}-{pair['b']}: {pair['score']:.1f}% ({pair['percent_a']}% / {pair['percent_b']}%)")
    return entry

# A pair is independent unless it is a copy and its original (dora is ann's, ed is ben's).
originals = {"dora": "ann", "ed": "ben"}
def independent_pair(pair):
    return len({originals.get(name, name) for name in pair}) == 2
copies = {frozenset(("ann", "dora")), frozenset(("ben", "ed"))}
for lab_name in ("01_words", "02_notes"):
    course = ranking(os.path.join(work, "course-out"), lab_name)
    pairs = [(frozenset((p["a"], p["b"])), p["score"]) for p in course["pairs"]]
    check({pair for pair, _ in pairs[:2]} == copies,
          f"{lab_name}: the first two pairs are {[sorted(p) for p, _ in pairs[:2]]}, expected ann-dora and ben-ed")
    copy_scores = [score for pair, score in pairs if pair in copies]
    independent = [score for pair, score in pairs if independent_pair(pair)]
    check(len(copy_scores) == 2 and min(copy_scores) > max(independent or [0]),
          f"{lab_name}: copies {copy_scores} do not all rank above the independent pairs (best {max(independent or [0])})")
    check(course["tool"] == ("sim_c" if lab_name == "01_words" else "sim_text"), f"{lab_name} was read by {course['tool']}")
html = open(os.path.join(work, "course-out", "similarity.html"), encoding="utf-8").read()
check("does not accuse" in html, "similarity.html does not say that it ranks and does not accuse")
check("<script" not in html.lower(), "similarity.html has a script")
check("tokens in common" in html, "similarity.html shows no shared run side by side")

if os.path.isdir(os.path.join(work, "tree-out")):
    tree = ranking(os.path.join(work, "tree-out"), lab)
    first = tree["pairs"][0] if tree["pairs"] else {}
    check({first.get("a"), first.get("b")} == {"alice", "frank"} and first.get("score", 0) >= 90,
          f"{lab}: the first pair is {first}, expected alice-frank at 90% or more")
    check(sorted(tree["left_out"]) == ["bea", "bob"], f"{lab}: left out {tree['left_out']}, expected bea and bob (stubs only)")
    check(all({"bob", "bea"}.isdisjoint((p["a"], p["b"])) for p in tree["pairs"]),
          f"{lab}: a pair has a student who handed in the stubs: the given code counted")
for message in failures:
    print("FAIL:", message)
sys.exit(1 if failures else 0)
PY
