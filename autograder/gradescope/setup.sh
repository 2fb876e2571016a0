#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image; the
# package (autograder/make-gradescope-package.sh) is unpacked in /autograder/source.
# It installs Stoa's dependencies and builds the framework and the grader from the
# student release in stoa/ (no tests). run_autograder then compiles each
# submission against that build.
#
# Overridable for a local try: STOA_SKIP_DEPS=1 skips the package installation.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
tree=$here/stoa
if [ "${STOA_SKIP_DEPS:-0}" != 1 ]; then
  bash "$tree/.ci/install-deps.sh"
fi
cmake -S "$tree" -B "$tree/build" -DSTOA_BUILD_TESTS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build "$tree/build" -j"$(nproc 2>/dev/null || echo 2)"
echo "setup.sh: built $tree/build (stoa-grade, stoa-grade-class, the exported framework)"
