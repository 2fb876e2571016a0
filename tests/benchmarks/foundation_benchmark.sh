#!/usr/bin/env bash
# tests/benchmarks/foundation_benchmark.sh [BUILD_DIR] [RUNS]
# Prints, as medians of RUNS runs (default 5):
#   - wall time to render lab 01's orbit_front (512x512) headless, per backend
#   - wall time to compare that image with its reference
#   - wall time to grade every case of labs 01-02 (stoa-grade, one job and two)
#   - a clean build of the tree and a rebuild after touching one lab file (one run each)
# The machines are shared and noisy: read ratios from one run, not absolutes across runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build-solutions}
runs=${2:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -n | awk '{ a[NR] = $1 } END { if (NR % 2) print a[(NR + 1) / 2]; else print (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
seconds() { local start end; start=$(date +%s.%N); "$@" >/dev/null 2>&1; end=$(date +%s.%N); awk -v a="$start" -v b="$end" 'BEGIN { print b - a }'; }
report() { printf '%-58s %8.3f s  (median of %d)\n' "$1" "$2" "$3"; }

reference="$root/autograder/references/01_transforms/orbit_front.png"
for backend in osmesa egl; do
  times=$(for _ in $(seq "$runs"); do seconds "$build/bin/lab01_transforms" --render orbit_front --output "$work/o.png" --backend "$backend"; done | median)
  report "render lab01 orbit_front 512x512 ($backend)" "$times" "$runs"
done
times=$(for _ in $(seq "$runs"); do seconds "$build/bin/compare_images" "$work/o.png" "$reference"; done | median)
report "compare with the reference (process incl. PNG decode)" "$times" "$runs"
for jobs in 1 2; do
  times=$(for _ in $(seq "$runs"); do seconds "$build/bin/stoa-grade" --lab 01_transforms --lab 02_shading --jobs "$jobs" --work-dir "$work/grade"; done | median)
  report "grade all cases of labs 01-02 (--jobs $jobs)" "$times" "$runs"
done

if [ "${STOA_BENCH_BUILD:-1}" = 1 ]; then
  clean="$work/clean-build"
  cmake -S "$root" -B "$clean" -DSTOA_USE_SOLUTIONS=ON -DSTOA_BUILD_TESTS=OFF >/dev/null
  report "clean build, solutions track, no tests (-j$(nproc))" "$(seconds cmake --build "$clean" -j"$(nproc)")" 1
  touch "$root/solutions/01_transforms/student/transforms.cpp"
  report "rebuild after touching solutions/01_transforms/student/transforms.cpp" "$(seconds cmake --build "$clean" -j"$(nproc)")" 1
fi
