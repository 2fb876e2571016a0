#!/usr/bin/env bash
# A student's loop: after editing one student file, how long `cmake --build` and
# `stoa-grade --lab NN` take. For each lab, touches its largest student .cpp (a
# lab whose student files are all GLSL needs no rebuild: the programs read GLSL
# at run time), rebuilds, and grades the lab; prints the median of RUNS runs.
# Run it on a student's build (cmake -S . -B build, the default configure), built once.
#
#   tests/benchmarks/student_rebuild_benchmark.sh BUILD_DIR [RUNS]
set -euo pipefail
build=${1:?usage: student_rebuild_benchmark.sh BUILD_DIR [RUNS]}
runs=${2:-3}
source=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$build" && pwd)
[ -x "$build/bin/stoa-grade" ] || { echo "no $build/bin/stoa-grade: build the tree first" >&2; exit 1; }
jobs=$(nproc 2>/dev/null || echo 2)
cmake --build "$build" -j"$jobs" > /dev/null   # start from an up-to-date build

median() { printf '%s\n' "$@" | sort -n | sed -n "$(( ($# + 1) / 2 ))p"; }
ms_since() { echo $(( ($(date +%s%N) - $1) / 1000000 )); }

printf '%-20s %-26s %12s %12s\n' lab "touched file" "rebuild" "stoa-grade"
for lab_dir in "$source"/labs/[0-9][0-9]_*/; do
  lab=$(basename "$lab_dir")
  # The .cpp files between STUDENT_FILES and APP_SOURCES in the lab's stoa_add_lab().
  files=$(tr '\n' ' ' < "$lab_dir/CMakeLists.txt" | sed -e 's/.*STUDENT_FILES//' -e 's/APP_SOURCES.*//' |
          grep -oE '[A-Za-z0-9_/]+\.cpp' || true)
  largest=""
  for file in $files; do
    file=student/$file
    if [ -z "$largest" ] || [ "$(wc -c < "$lab_dir/$file")" -gt "$(wc -c < "$lab_dir/$largest")" ]; then largest=$file; fi
  done
  rebuilds=() grades=()
  for run in $(seq "$runs"); do
    if [ -n "$largest" ]; then
      touch "$lab_dir/$largest"
      start=$(date +%s%N)
      cmake --build "$build" -j"$jobs" > /dev/null
      rebuilds+=("$(ms_since "$start")")
    fi
    start=$(date +%s%N)
    "$build/bin/stoa-grade" --lab "$lab" --jobs "$jobs" > /dev/null 2>&1 || true
    grades+=("$(ms_since "$start")")
  done
  if [ -n "$largest" ]; then
    rebuild=$(awk -v ms="$(median "${rebuilds[@]}")" 'BEGIN { printf "%.1f s", ms / 1000 }')
  else
    largest="(GLSL only)" rebuild="none"
  fi
  grade=$(awk -v ms="$(median "${grades[@]}")" 'BEGIN { printf "%.1f s", ms / 1000 }')
  printf '%-20s %-26s %12s %12s\n' "$lab" "$largest" "$rebuild" "$grade"
done
