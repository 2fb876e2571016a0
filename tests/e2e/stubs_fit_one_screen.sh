#!/bin/sh
# The stubs' report (what a fresh clone's `stoa-grade` prints) says every case
# is not attempted and fits one screen: at most 20 lines on standard output,
# ending with the lab to start with and the score. The progress goes to
# standard error.
#   stubs_fit_one_screen.sh STOA_GRADE WORK_DIR [stoa-grade arguments...]
set -eu
grade=$1 work=$2
shift 2
mkdir -p "$work"
"$grade" --expect not-attempted --jobs 2 --work-dir "$work/run" "$@" >"$work/report.txt" 2>"$work/progress.txt" || {
  echo "FAIL: stoa-grade --expect not-attempted failed"; cat "$work/report.txt" "$work/progress.txt"; exit 1; }
lines=$(wc -l <"$work/report.txt")
cat "$work/report.txt"
[ "$lines" -le 20 ] || { echo "FAIL: the report has $lines lines on standard output; a fresh clone's must fit 20"; exit 1; }
grep -q '^next: lab 01_transforms, docs/labs/01_transforms.md$' "$work/report.txt" ||
  { echo "FAIL: no 'next:' line naming lab 01"; exit 1; }
if grep -q 'cascade\]' "$work/report.txt"; then echo "FAIL: cascade rows that say nothing new"; exit 1; fi
[ -s "$work/progress.txt" ] || { echo "FAIL: no progress on standard error"; exit 1; }
echo "one screen: $lines lines"
