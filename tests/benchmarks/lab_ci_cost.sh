#!/usr/bin/env bash
# What one lab adds to CI's test stages (.ci/test-all.sh; issue 8's budget: at most
# 2.5 minutes per lab). Runs, for lab LAB alone and two at a time as `ctest -j2`
# does, every grading command of the end-to-end matrix that covers each lab:
#   solutions build:  the solutions on both backends and under the 5 instruction-set
#                     limits, the stubs, its planted mistakes, its equivalents, the
#                     determinism check, and stoa-grade-class on 6 submissions of the
#                     lab (the 4 students of e2e.grade_class, the 2 of e2e.gradescope_package);
#   sanitizer build:  the solutions on EGL and one batch-graded student (when BUILD_SAN is given).
# The lab's share of the two builds is read from their .ninja_log (CPU seconds / cores).
#
#   tests/benchmarks/lab_ci_cost.sh LAB BUILD_SOLUTIONS [BUILD_SAN]
#   tests/benchmarks/lab_ci_cost.sh 05_shadows build-solutions build-sanitize
set -euo pipefail
lab=${1:?usage: lab_ci_cost.sh LAB BUILD_SOLUTIONS [BUILD_SAN]}
sol=$(cd "${2:?usage: lab_ci_cost.sh LAB BUILD_SOLUTIONS [BUILD_SAN]}" && pwd)
san=${3:+$(cd "$3" && pwd)}
source=$(cd "$(dirname "$0")/../.." && pwd)
cores=$(nproc 2>/dev/null || echo 2)
work=$(mktemp -d "${TMPDIR:-/tmp}/stoa-lab-cost.XXXXXX")
trap 'rm -rf "$work"' EXIT

build_share() {   # CPU seconds of the lab's edges in a .ninja_log, over the cores
  python3 - "$1/.ninja_log" "$lab" "$cores" <<'PY'
import re, sys
path, lab, cores = sys.argv[1], sys.argv[2], int(sys.argv[3])
number = lab.split("_")[0]
edges = {}
for line in open(path).read().splitlines()[1:]:
    fields = line.split("\t")
    if len(fields) >= 4:
        edges[fields[3]] = (int(fields[1]) - int(fields[0])) / 1000
mine = sum(seconds for output, seconds in edges.items() if lab in output or f"lab{number}_" in output)
print(f"{mine / cores:.1f}")
PY
}

# The lab's submissions: made from the stubs with the solutions pasted in.
python3 "$source/tests/e2e/make_submission.py" "$source" "$work/made" > /dev/null
mkdir -p "$work/class" "$work/class-san"
for student in s1 s2 s3 s4 s5 s6; do cp -r "$work/made" "$work/class/$student"; done
cp -r "$work/made" "$work/class-san/s1"

commands="$work/commands.txt"
g="$sol/bin/stoa-grade --lab $lab --jobs 2"
{
  echo "$g --backend osmesa --expect pass --work-dir $work/w1"
  echo "$g --backend egl --expect pass --work-dir $work/w2"
  echo "$g --bin-dir $sol/bin/stubs --expect not-attempted --work-dir $work/w3"
  echo "$g --check-mistakes --work-dir $work/w4"
  n=5
  for caps in sse4.1/osmesa sse4.1/egl sse2/egl nosse/osmesa nosse/egl; do
    echo "env GALLIUM_OVERRIDE_CPU_CAPS=${caps%/*} $g --backend ${caps#*/} --expect pass --timeout 120 --work-dir $work/w$n"
    n=$((n + 1))
  done
  for equivalent in "$sol"/bin/equivalents/"$lab".*/; do
    [ -d "$equivalent" ] || continue
    echo "$g --bin-dir $equivalent --expect pass --work-dir $work/w$n"
    n=$((n + 1))
  done
  echo "$g --determinism --work-dir $work/w$n"
  echo "$sol/bin/stoa-grade-class $work/class --out $work/class-out --jobs 2 --lab $lab"
  if [ -n "$san" ]; then
    echo "$san/bin/stoa-grade --lab $lab --jobs 2 --backend egl --expect pass --work-dir $work/s1"
    echo "$san/bin/stoa-grade-class $work/class-san --out $work/class-san-out --jobs 2 --lab $lab"
  fi
} > "$commands"

start=$(date +%s%N)
# Two at a time, as ctest -j2 runs them; each must succeed.
xargs -P 2 -I{} sh -c '{} > /dev/null 2>&1 || { echo "failed: {}" >&2; exit 255; }' < "$commands"
tests=$(( ($(date +%s%N) - start) / 1000000 ))

sol_build=$(build_share "$sol")
san_build=0
[ -n "$san" ] && san_build=$(build_share "$san")
python3 - "$lab" "$tests" "$sol_build" "$san_build" "$(wc -l < "$commands")" <<'PY'
import sys
lab, tests, sol_build, san_build, count = sys.argv[1], int(sys.argv[2]) / 1000, float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
total = tests + sol_build + san_build
print(f"{lab}: tests {tests:.0f} s ({count} grading commands, two at a time), "
      f"builds {sol_build:.0f} s + {san_build:.0f} s (sanitizer): {total:.0f} s = {total / 60:.1f} min")
PY
