#!/usr/bin/env bash
# release_paths_catch.sh PYTHON SOURCE_DIR WORK_DIR
# autograder/check-release-paths.py on a copy of the student release's files
# (the tree without solutions/ and tests/labs/): it passes, and it fails once a
# lab page points at a file or program the release leaves out.
set -euo pipefail
python=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
(cd "$source" && git ls-files -z --cached --others --exclude-standard 2>/dev/null ||
                 find . -type f -not -path './.git/*' -print0) |
  while IFS= read -r -d '' file; do
    case "$file" in solutions/*|tests/labs/*|build*/*|site/*) continue ;; esac
    [ -f "$source/$file" ] || continue
    mkdir -p "$work/$(dirname "$file")"
    cp "$source/$file" "$work/$file"
  done
"$python" "$source/autograder/check-release-paths.py" "$work" ||
  { echo "FAIL: the release as it is does not pass"; exit 1; }

printf '\nThe tests in `tests/labs/NormalsTests.cpp` check it; run `build/bin/stoa-tests-labs`.\n' \
  >> "$work/docs/labs/03_meshes.md"
printf '// See shaders/common/no_such_file.glsl.\n' >> "$work/labs/02_shading/student/lighting.glsl"
status=0
"$python" "$source/autograder/check-release-paths.py" "$work" > "$work/out.txt" || status=$?
cat "$work/out.txt"
[ "$status" -eq 1 ] || { echo "FAIL: exit status $status for pointers to missing files (expected 1)"; exit 1; }
for expected in "points at tests/labs/NormalsTests.cpp" "points at build/bin/stoa-tests-labs" \
                "labs/02_shading/student/lighting.glsl:"; do
  grep -qF "$expected" "$work/out.txt" || { echo "FAIL: nothing reported for '$expected'"; exit 1; }
done
echo "PASS: the pointers to missing files were reported"
