#!/usr/bin/env bash
# The developers' inner loop: builds what the quick tests need in the solutions
# build (build-solutions/, the folder .ci/test-all.sh uses, so an incremental
# build is quick) and runs `ctest -L quick`: the unit tests, the GL tests on EGL
# and the grading of lab 01's solutions. About a minute or two after an edit;
# .ci/test-all.sh stays the full run.
#
#   .ci/quick.sh [extra ctest arguments, e.g. -R Camera]
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
if [ ! -f build-solutions/CMakeCache.txt ]; then
  generator=()
  command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
  launcher=()
  command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  cmake "${generator[@]}" "${launcher[@]}" -S . -B build-solutions -DSTOA_USE_SOLUTIONS=ON \
        -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG"
fi
cmake --build build-solutions -j"$jobs" --target stoa-tests-core stoa-tests-gl stoa-grade hostile_lab 01_transforms
ctest --test-dir build-solutions -L quick -j"$jobs" --output-on-failure "$@"
