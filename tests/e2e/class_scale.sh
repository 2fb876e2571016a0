#!/usr/bin/env bash
# The class report at scale: a made-up class (make_class.py: finished labs,
# equivalent rewrites, planted mistakes, stubs, compile errors) graded with
# stoa-grade-class, then the figures: time per student, the class report's size
# and the time to write it, the time headless Chromium takes to load it, the
# similarity pass on the same class. Not a ctest test: 200 students take tens
# of minutes. Its figures are in docs/instructor-guide.md ("The class report").
#
#   class_scale.sh <build dir> <work dir> [STUDENTS (200)] [JOBS (2)] [LAB...]   (labs: the first two)
set -euo pipefail
build=$(cd "$1" && pwd) work=$2 students=${3:-200} jobs=${4:-2}
shift $(( $# < 4 ? $# : 4 ))
source=$(cd "$(dirname "$0")/../.." && pwd)
labs=("$@")
[ ${#labs[@]} -gt 0 ] || mapfile -t labs < <(cd "$source/labs" && ls -d [0-9][0-9]_* | head -2)
lab_options=()
for lab in "${labs[@]}"; do lab_options+=(--lab "$lab"); done
seconds() { python3 -c "import time; print(f'{time.time():.3f}')"; }
elapsed() { python3 -c "print(round($(seconds) - $1, 1))"; }

rm -rf "$work" && mkdir -p "$work"
python3 "$(dirname "$0")/make_class.py" "$source" "$work/submissions" "$students" "${labs[@]}"

start=$(seconds)
"$build/bin/stoa-grade-class" "$work/submissions" --out "$work/out" --jobs "$jobs" "${lab_options[@]}" > "$work/grade.log" 2>&1
grading=$(elapsed "$start")
report_line=$(grep "class.html and class.json" "$work/grade.log" || true)

start=$(seconds)
"$build/bin/stoa-grade-class" --report-from "$work/out" --out "$work/from-out" > "$work/report-from.log" 2>&1
report_from=$(elapsed "$start")

start=$(seconds)
"$build/bin/stoa-grade-class" "$work/submissions" --out "$work/similarity" --similarity-only "${lab_options[@]}" \
    > "$work/similarity.log" 2>&1
similarity=$(elapsed "$start")

# Load time in headless Chromium: a page that times the report loading in a
# frame (its load event waits for the frame's), against an empty frame.
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
load_times=""
if [ -n "$browser" ]; then
  : > "$work/empty.html"
  for page in class.html empty.html; do
    path=$work/out/$page
    [ "$page" = empty.html ] && path=$work/empty.html
    cat > "$work/time-$page" <<EOF
<!DOCTYPE html><html><head><title>-</title></head><body>
<script>const start = performance.now();</script>
<iframe style="width:1280px;height:900px" src="file://$path"
        onload="document.title = 'load ms ' + Math.round(performance.now() - start)"></iframe></body></html>
EOF
    for run in 1 2 3; do
      "$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files --dump-dom \
          "file://$work/time-$page" 2>/dev/null | grep -o '<title>load ms [0-9]*' | grep -o '[0-9]*$' \
          >> "$work/load-$page.txt" || true
    done
    load_times+="$page $(tr '\n' ' ' < "$work/load-$page.txt")ms; "
  done
  "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --screenshot="$work/class.png" \
      --window-size=1280,900 "file://$work/out/class.html" >/dev/null 2>&1 || true
fi

echo
echo "== stoa-grade-class, $students students, labs ${labs[*]}, --jobs $jobs =="
tail -1 "$work/grade.log"
python3 - "$work/out/gradebook.csv" <<'PY'
import collections, csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("  statuses: " + ", ".join(f"{n} {s}" for s, n in collections.Counter(r["status"] for r in rows).most_common()))
PY
echo "grading:                $grading s, $(python3 -c "print(round($grading / $students, 2))") s per student (wall, $jobs at once)"
echo "class report:           $report_line"
echo "  class.html            $(stat -c %s "$work/out/class.html") bytes"
echo "  class.json            $(stat -c %s "$work/out/class.json") bytes"
echo "--report-from:          $report_from s for $students results.json files (reading and writing)"
echo "similarity (--similarity-only): $similarity s; $(grep 'similarity took' "$work/similarity.log" || true)"
echo "  similarity.html       $(stat -c %s "$work/similarity/similarity.html" 2>/dev/null || echo '?') bytes"
echo "  similarity.json       $(stat -c %s "$work/similarity/similarity.json" 2>/dev/null || echo '?') bytes"
echo "headless Chromium load (3 runs each, the frame's load event): ${load_times:-no chromium}"
echo "screenshot:             $work/class.png"
