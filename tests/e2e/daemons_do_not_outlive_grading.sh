#!/bin/sh
# The attack of issue 15 through the real stoa-grade: every case of lab 01 is
# rendered by tests/grader/hostile_lab, which leaves a double-forked, setsid()
# daemon behind (and one that keeps re-forking, and one that closes its
# descriptors and renames itself). Each daemon reads the --json, --html and
# --junit paths from its ancestors' command lines and, a second later,
# overwrites them with a perfect score, as do the references it is pointed at.
# A few seconds after stoa-grade has exited, the reports and references must
# be as stoa-grade wrote them and no process of the submission may be alive.
#   daemons_do_not_outlive_grading.sh STOA_GRADE HOSTILE_LAB SOURCE_DIR WORK_DIR
set -eu
grade=$1
hostile=$2
source_dir=$3
work=$4
rm -rf "$work"
mkdir -p "$work/bin" "$work/references"
ln -s "$hostile" "$work/bin/lab01_transforms"
cp "$source_dir"/autograder/references/01_transforms/*.png "$work/references/"
cd "$work"

marker="stoa-daemon-$$-$(date +%s%N)"
status=0
for kind in rewrite refork stealth; do
  start=$(date +%s%N)
  # stoa-grade exits 0 with every case failed; the relative paths are the ones in the issue.
  STOA_HOSTILE_DAEMON=$kind STOA_HOSTILE_DELAY=1 STOA_HOSTILE_MARK=$marker \
  STOA_HOSTILE_REFERENCES="$work/references" \
    "$grade" --bin-dir bin --lab 01_transforms --json results-$kind.json --html report-$kind.html \
             --junit junit-$kind.xml --work-dir images-$kind --jobs 2 > grade-$kind.log 2>&1 ||
    { echo "FAIL: stoa-grade exited with status $? ($kind); see $work/grade-$kind.log"; status=1; }
  end=$(date +%s%N)
  echo "$kind: graded in $(( (end - start) / 1000000 )) ms"
  if ! grep -q 'left [0-9]* process.* running after it exited (killed)' results-$kind.json; then
    echo "FAIL: results-$kind.json does not say that the lab program left processes running"; status=1
  fi
  if grep -q '"score": 100' results-$kind.json; then echo "FAIL: results-$kind.json is forged already"; status=1; fi
done
cksum results-*.json report-*.html junit-*.xml references/*.png > before.txt

# The daemons waited 1 s; had one survived, it would have written by now.
sleep 3
cksum results-*.json report-*.html junit-*.xml references/*.png > after.txt
if ! cmp -s before.txt after.txt; then
  echo "FAIL: a report or a reference changed after stoa-grade had exited:"; diff before.txt after.txt || true
  status=1
fi
for environ in /proc/[0-9]*/environ; do
  if grep -q "$marker" "$environ" 2>/dev/null; then
    pid=${environ#/proc/}; pid=${pid%/environ}
    echo "FAIL: process $pid ($(cat /proc/$pid/comm 2>/dev/null)) of the submission is still alive"; status=1
  fi
done
ls -a | grep '^\..*\.json\.' && { echo "FAIL: a temporary report was left behind"; status=1; }
[ "$status" -eq 0 ] && echo "the reports, the references and the machine are clean 3 s after grading"
exit "$status"
