#!/usr/bin/env bash
# How long grading a lab whose program hangs takes (issue 8: at most 30 s).
# A stand-in lab program that never answers is graded with the real cases,
# references and recorded render times of each lab; prints the wall time per lab,
# the median of RUNS runs.
#
#   tests/benchmarks/hanging_lab_benchmark.sh BUILD_DIR [RUNS] [LAB...]
#   tests/benchmarks/hanging_lab_benchmark.sh build-solutions 3 01_transforms 05_shadows
set -euo pipefail
build=${1:?usage: hanging_lab_benchmark.sh BUILD_DIR [RUNS] [LAB...]}
runs=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
source=$(cd "$(dirname "$0")/../.." && pwd)
grade=$(cd "$build" && pwd)/bin/stoa-grade
[ -x "$grade" ] || { echo "no $grade: build the tree first" >&2; exit 1; }
labs=("$@")
[ ${#labs[@]} -gt 0 ] || labs=($(cd "$source/labs" && ls -d [0-9][0-9]_*/ | tr -d /))

work=$(mktemp -d "${TMPDIR:-/tmp}/stoa-hanging.XXXXXX")
trap 'rm -rf "$work"' EXIT
for lab in "${labs[@]}"; do
  program="$work/bin/lab${lab%%_*}_${lab#*_}"
  mkdir -p "$work/bin"
  printf '#!/bin/sh\n# A lab program that hangs.\nexec sleep 1000\n' > "$program"
  chmod +x "$program"
  times=()
  for run in $(seq "$runs"); do
    start=$(date +%s%N)
    "$grade" --bin-dir "$work/bin" --lab "$lab" --work-dir "$work/grade" > "$work/out.txt" 2>&1 || true
    times+=($(( ($(date +%s%N) - start) / 1000000 )))
    grep -q "timed out" "$work/out.txt" || { echo "$lab: the grader did not report a timeout:"; cat "$work/out.txt"; exit 1; }
  done
  cases=$(grep -c '^\[[0-9]*/[0-9]*] .* ... error' "$work/out.txt" || true)
  median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$(( (runs + 1) / 2 ))p")
  printf '%-20s %2d cases timed out   median %6.1f s of %d runs (%s ms)\n' "$lab" "$cases" \
         "$(echo "$median" | awk '{print $1 / 1000}')" "$runs" "${times[*]}"
  rm -f "$program"
done
