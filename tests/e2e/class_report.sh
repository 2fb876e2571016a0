#!/usr/bin/env bash
# The class report (class.html, class.json) of a small class graded on the first
# lab, made as grade_class.sh makes its submissions (make_submission.py):
#   alice   finished                                   -> full marks
#   bob     the stubs                                  -> not attempted
#   carol   finished, with a compile error             -> "did not compile", with the error line
#   dave    finished, with the lab's planted mistake view_without_translation (or its first)
#   erin    the same mistake                           -> the first thing to teach again: 2 students
# Checks class.json's numbers against gradebook.csv (points, totals, histograms,
# means, medians), the page (escaped, no script, links to the students' reports),
# a headless-browser screenshot with the histogram's bars in the first screen
# (when chromium is installed), and --report-from: on the grading's own folder,
# on a Gradescope-like export of STUDENT.json files with one malformed file, and
# on a folder that does not exist.
#
#   class_report.sh <stoa-grade-class> <source dir> <work dir>
set -euo pipefail
grade_class=$1 source=$2 work=$3
here=$(dirname "$0")
[ -d "$source/solutions" ] || { echo "class_report.sh: no solutions/ in $source: nothing to make the class from"; exit 77; }
lab=$(cd "$source/labs" && ls -d [0-9][0-9]_* | head -1)
rm -rf "$work"
mkdir -p "$work/submissions" "$work/make"

python3 "$here/make_submission.py" "$source" "$work/submissions/alice/labs" >/dev/null
mkdir -p "$work/submissions/bob" && cp -r "$source/labs" "$work/submissions/bob/"
python3 "$here/make_submission.py" "$source" "$work/submissions/carol/labs" >/dev/null
broken=$(cd "$work/submissions/carol/labs/$lab/student" && ls *.cpp | head -1)
echo "this is not C++;" >> "$work/submissions/carol/labs/$lab/student/$broken"
mistake=$(ls "$source/solutions/$lab/mistakes/view_without_translation.mistake" 2>/dev/null ||
          ls "$source/solutions/$lab/mistakes/"*.mistake | head -1)
for student in dave erin; do
  python3 "$here/make_submission.py" "$source" "$work/submissions/$student/labs" >/dev/null
  python3 - "$mistake" "$work/submissions/$student/labs/$lab/student" <<'PY'
import os, re, sys
mistake, folder = sys.argv[1:3]
text = open(mistake).read()
name = re.search(r"^file:\s*(\S+)", text, re.M).group(1)
find = text.split("--- find\n", 1)[1].split("--- replace\n", 1)[0]
replace = text.split("--- replace\n", 1)[1].split("--- end", 1)[0]
path = os.path.join(folder, name)
code = open(path).read()
assert code.count(find) == 1, f"{mistake}: the find text is not in {path} once"
open(path, "w").write(code.replace(find, replace))
PY
done

start=$(date +%s.%N)
"$grade_class" "$work/submissions" --out "$work/out" --jobs 2 --lab "$lab" | tee "$work/grade.log"
echo "graded in $(python3 -c "import sys; print(round($(date +%s.%N) - $start, 1))") s"

browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
if [ -n "$browser" ]; then
  "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --screenshot="$work/class.png" \
      --window-size=1280,900 "file://$work/out/class.html" >/dev/null 2>&1
  echo "screenshot: $work/class.png"
else
  echo "no chromium: the screenshot is skipped"
fi

# --report-from: the grading's own folder, a Gradescope-like export, a missing folder.
"$grade_class" --report-from "$work/out" --out "$work/from-out"
mkdir -p "$work/export"
for student in alice bob carol dave erin; do cp "$work/out/$student/results.json" "$work/export/$student.json"; done
echo '{"score": 3, "tests": [{"name": "01_x/a", "score": ' > "$work/export/mallory.json"
"$grade_class" --report-from "$work/export" 2> "$work/export.err"
cat "$work/export.err"
set +e
"$grade_class" --report-from "$work/no-such-folder" 2> "$work/missing.err"
missing_status=$?
set -e
cat "$work/missing.err"

python3 "$here/check_class_report.py" "$work" "$lab" "$(basename "$mistake" .mistake)" "$missing_status"
