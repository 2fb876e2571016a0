#!/usr/bin/env bash
# tests/benchmarks/grading_benchmark.sh [BUILD_DIR] [RUNS] [STUDENTS] [BATCH_LABS]
# What grading costs beyond rendering, and how batch grading scales.
#
# 1. Overhead: every public case of every built lab rendered by its lab program
#    directly, one after the other (the raw render time, summed), against
#    `stoa-grade --jobs 1` grading the same cases (child processes, limits,
#    reference guard, compare, FLIP where needed, reports). Target: at most 1.5x.
#    Then `stoa-grade --jobs 2`, and its speedup over one job.
# 2. Batch scaling (STUDENTS > 0, default 0 because it compiles every student):
#    stoa-grade-class on STUDENTS copies of the solutions with --jobs 1 and
#    --jobs $(nproc); prints the wall times and the speedup. BATCH_LABS (e.g.
#    "01_transforms,02_shading") limits the batch to those labs: each student's
#    build then compiles less, and the batch part takes minutes, not an hour.
# Medians of RUNS runs (default 5). The machines are shared and noisy: read the
# ratios, which come from runs taken side by side, not the absolute times.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build-solutions}
runs=${2:-5}
students=${3:-0}
batch_labs=()
IFS=',' read -r -a batch_lab_names <<< "${4:-}"
for lab in "${batch_lab_names[@]}"; do [ -n "$lab" ] && batch_labs+=(--lab "$lab"); done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -x "$build/bin/stoa-grade" ] || { echo "grading_benchmark: no $build/bin/stoa-grade; build first" >&2; exit 1; }

median() { sort -n | awk '{ a[NR] = $1 } END { if (NR % 2) print a[(NR + 1) / 2]; else print (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f\n", b - a }'; }
report() { printf '%-64s %8.3f s  (median of %d)\n' "$1" "$2" "$3"; }

labs="" cases=""
for manifest in "$root"/labs/[0-9][0-9]_*/cases.ini; do
  lab=$(basename "$(dirname "$manifest")")
  [ -x "$build/bin/lab$lab" ] || continue
  labs="$labs $lab"
  cases="$cases $(sed -n 's/^\[case \(.*\)\]$/\1/p' "$manifest" | tr '\n' ' ')"
done
[ -n "$labs" ] || { echo "grading_benchmark: no lab program in $build/bin" >&2; exit 1; }
count=$(echo $cases | wc -w)
grade_args=()
for lab in $labs; do grade_args+=(--lab "$lab"); done
for name in $cases; do grade_args+=(--case "$name"); done
echo "labs:$labs; $count public cases"

raw_all="" one_all="" two_all=""
for _ in $(seq "$runs"); do
  start=$(now)
  for lab in $labs; do
    for name in $(sed -n 's/^\[case \(.*\)\]$/\1/p' "$root/labs/$lab/cases.ini"); do
      "$build/bin/lab$lab" --render "$name" --output "$work/raw.png" >/dev/null 2>&1
    done
  done
  raw_all="$raw_all $(elapsed "$start" "$(now)")"
  start=$(now)
  "$build/bin/stoa-grade" "${grade_args[@]}" --jobs 1 --work-dir "$work/one" >/dev/null 2>&1 || true
  one_all="$one_all $(elapsed "$start" "$(now)")"
  start=$(now)
  "$build/bin/stoa-grade" "${grade_args[@]}" --jobs 2 --work-dir "$work/two" >/dev/null 2>&1 || true
  two_all="$two_all $(elapsed "$start" "$(now)")"
done
raw=$(echo $raw_all | tr ' ' '\n' | median)
one=$(echo $one_all | tr ' ' '\n' | median)
two=$(echo $two_all | tr ' ' '\n' | median)
report "raw renders of the $count public cases, one after the other" "$raw" "$runs"
report "stoa-grade --jobs 1, the same cases" "$one" "$runs"
report "stoa-grade --jobs 2, the same cases" "$two" "$runs"
awk -v r="$raw" -v o="$one" -v t="$two" 'BEGIN {
  printf "grading / raw renders (--jobs 1): %.2fx  (target <= 1.5x)\n", o / r
  printf "speedup of --jobs 2 over --jobs 1: %.2fx\n", o / t }'

if [ "$students" -gt 0 ] && [ "$(nproc)" -lt 2 ]; then
  echo "grading_benchmark: one core, so no batch scaling to measure; skipping the batch part"
elif [ "$students" -gt 0 ]; then
  [ -x "$build/bin/stoa-grade-class" ] || { echo "grading_benchmark: no stoa-grade-class in $build/bin" >&2; exit 1; }
  mkdir -p "$work/class"
  for i in $(seq "$students"); do
    dest="$work/class/student$i/labs"
    mkdir -p "$dest"
    cp -r "$root"/labs/. "$dest"/
    for lab_dir in "$root"/solutions/[0-9][0-9]_*/; do
      lab=$(basename "$lab_dir")
      for file in "$lab_dir"*; do
        if [ -f "$file" ] && [ -f "$dest/$lab/$(basename "$file")" ]; then cp "$file" "$dest/$lab/"; fi
      done
    done
  done
  cores=$(nproc)
  # RUNS rounds; the order of the two settings alternates, so that whatever the
  # first batch warms (page cache, Mesa's shader cache) favours neither.
  class_one="" class_all=""
  for round in $(seq "$runs"); do
    if [ $((round % 2)) -eq 1 ]; then order="1 $cores"; else order="$cores 1"; fi
    for jobs in $order; do
      rm -rf "$work/class-out-$jobs"
      start=$(now)
      "$build/bin/stoa-grade-class" "$work/class" --out "$work/class-out-$jobs" --jobs "$jobs" "${batch_labs[@]}" \
        >/dev/null 2>&1
      took=$(elapsed "$start" "$(now)")
      # Every student must have graded: a batch that failed fast is not a speedup.
      graded=$(tail -n +2 "$work/class-out-$jobs/gradebook.csv" | grep -c ',graded' || true)
      [ "$graded" -eq "$students" ] || { echo "grading_benchmark: only $graded of $students students graded" >&2; exit 1; }
      if [ "$jobs" = 1 ]; then class_one="$class_one $took"; else class_all="$class_all $took"; fi
    done
  done
  one=$(echo $class_one | tr ' ' '\n' | median)
  all=$(echo $class_all | tr ' ' '\n' | median)
  report "stoa-grade-class, $students students${4:+ ($4)}, --jobs 1" "$one" "$runs"
  report "stoa-grade-class, $students students${4:+ ($4)}, --jobs $cores" "$all" "$runs"
  awk -v a="$one" -v b="$all" -v c="$cores" 'BEGIN { printf "batch speedup with %d jobs: %.2fx\n", c, a / b }'
fi
