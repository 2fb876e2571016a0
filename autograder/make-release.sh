#!/usr/bin/env bash
# Makes the student release of this tree in OUT_DIR and verifies it.
#
#   autograder/make-release.sh OUT_DIR [--classroom] [--jobs N] [--no-verify] [--cmake-args "ARGS"]
#
# The release is the tree without solutions/ (the filled-in labs, the planted
# mistakes, the hidden cases and their references all live there), without
# tests/labs/ (they check the solutions against independent implementations of
# the lab functions, and build only with solutions), without tests/data/out_of_gallery/ and tests/data/variants/
# (mistakes outside the gallery: patches of the solutions), without the framework's
# own tile assignment (framework/src/render/TileLightBinner.cpp: lab 08's answer by
# another road; the release's editor and showcase draw the student's lists), without
# .git and build folders. --classroom adds the GitHub Classroom workflow
# (autograder/classroom/grade.yml) as .github/workflows/grade.yml. Then, unless --no-verify:
#   1. no student file in labs/ equals its twin in solutions/, and no line that only
#      the solution has (a line of 40 characters or more) occurs anywhere in the release,
#      but for generic lines an instructor has listed in autograder/release-allowed-lines.txt;
#   2. every reference image belongs to a public case of its lab's cases.ini;
#   3. no page or comment a student reads points at a file the release leaves out
#      (autograder/check-release-paths.py);
#   4. the release configures and builds from a clean folder, as a student's would
#      (RelWithDebInfo; --cmake-args adds configure arguments after it, as e2e.student_release's
#      "-DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O0 -DCMAKE_C_FLAGS_RELEASE=-O0",
#      which builds without optimization or debug info);
#   5. its stoa-grade reports every case "not attempted" (--expect not-attempted).
# Exit status 0 when the release is made and verified, 1 otherwise, 2 on bad usage.
set -euo pipefail

usage() { sed -n '4p' "$0" | sed 's/^#  *//' >&2; exit 2; }
out="" jobs=$(nproc 2>/dev/null || echo 2) verify=1 classroom=0 cmake_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) [ $# -ge 2 ] || usage; jobs=$2; shift 2 ;;
    --no-verify) verify=0; shift ;;
    --cmake-args) [ $# -ge 2 ] || usage; read -r -a cmake_args <<< "$2"; shift 2 ;;
    --classroom) classroom=1; shift ;;
    -h|--help) sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "make-release: unknown option $1" >&2; usage ;;
    *) [ -z "$out" ] || usage; out=$1; shift ;;
  esac
done
[ -n "$out" ] || usage

source=$(cd "$(dirname "$0")/.." && pwd)
[ -d "$source/labs" ] || { echo "make-release: $source is not a Stoa tree (no labs/)" >&2; exit 1; }
if [ -e "$out" ] && [ -n "$(ls -A "$out" 2>/dev/null)" ]; then
  echo "make-release: $out exists and is not empty; remove it or pick another folder" >&2
  exit 1
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
# Inside the tree only under a build folder (ignored by git, skipped below).
case "$out/" in
  "$source"/build*/*) ;;
  "$source"/*) echo "make-release: OUT_DIR must be outside the tree ($source) or under a build folder" >&2; exit 1 ;;
esac

# What goes in: the files git knows (tracked, and new ones it does not ignore), or
# every file when this is not a git checkout; never solutions/, .git or build folders.
list_files() {
  if git -C "$source" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git -C "$source" ls-files -z --cached --others --exclude-standard
  else
    (cd "$source" && find . -type f -not -path './.git/*' -print0 | sed -z 's|^\./||')
  fi
}
count=0
while IFS= read -r -d '' file; do
  case "$file" in
    solutions/*|tests/labs/*|tests/data/out_of_gallery/*|tests/data/variants/*|.git/*|build*/*|site/*|*/__pycache__/*) continue ;;
    framework/src/render/TileLightBinner.cpp) continue ;;
  esac
  [ -f "$source/$file" ] || continue            # deleted in the work tree
  mkdir -p "$out/$(dirname "$file")"
  cp -p "$source/$file" "$out/$file"
  count=$((count + 1))
done < <(list_files)
if [ "$classroom" -eq 1 ]; then
  mkdir -p "$out/.github/workflows"
  cp "$source/autograder/classroom/grade.yml" "$out/.github/workflows/grade.yml"
  count=$((count + 1))
fi
echo "make-release: copied $count files into $out (without solutions/, tests/labs/, tests/data/out_of_gallery/, tests/data/variants/, the framework's tile assignment, .git, build folders)"
[ "$verify" -eq 1 ] || exit 0

failures=0
fail() { echo "make-release: FAIL: $*" >&2; failures=$((failures + 1)); }

echo "== 1. no solution text in the release"
[ ! -e "$out/solutions" ] || fail "the release has a solutions/ folder"
[ ! -e "$out/framework/src/render/TileLightBinner.cpp" ] || fail "the release has the framework's tile assignment"
if [ -d "$source/solutions" ]; then
  lines=$(mktemp)
  for solution_lab in "$source"/solutions/[0-9][0-9]_*/; do
    lab=$(basename "$solution_lab")
    for solution in "$solution_lab"student/*; do
      [ -f "$solution" ] || continue
      name=$(basename "$solution")
      student="$out/labs/$lab/student/$name"
      [ -f "$student" ] || fail "solutions/$lab/student/$name has no twin labs/$lab/student/$name in the release"
      [ -f "$student" ] || continue
      if cmp -s "$solution" "$student"; then fail "labs/$lab/student/$name is identical to its solution"; fi
      # Lines only the solution has, long enough to be telling.
      grep -vxF -f "$source/labs/$lab/student/$name" "$solution" | sed 's/^[[:space:]]*//' |
        awk 'length($0) >= 40' >> "$lines" || true
    done
  done
  # Generic lines (a loop header, a declaration) that may occur elsewhere.
  allowed="$source/autograder/release-allowed-lines.txt"
  if [ -f "$allowed" ] && [ -s "$lines" ]; then
    grep -v '^#' "$allowed" | sed 's/^[[:space:]]*//' | grep -v '^$' > "$lines.allowed" || true
    if [ -s "$lines.allowed" ]; then
      grep -vxF -f "$lines.allowed" "$lines" > "$lines.kept" || true
      mv "$lines.kept" "$lines"
    fi
    rm -f "$lines.allowed"
  fi
  if [ -s "$lines" ]; then
    while IFS= read -r leak; do
      fail "solution text in the release: $leak (if the line is generic, add it to autograder/release-allowed-lines.txt)"
    done < <(cd "$out" && grep -rlF -f "$lines" . | sed 's|^\./||' | while IFS= read -r file; do
               echo "$file: $(grep -nF -f "$lines" "$file" | head -1)"
             done)
  fi
  echo "   $(sort -u "$lines" | wc -l) solution-only lines checked against every file"
  rm -f "$lines"
else
  echo "   (this tree has no solutions/: nothing to compare)"
fi

echo "== 2. reference images belong to public cases"
for lab_refs in "$out"/autograder/references/*/; do
  [ -d "$lab_refs" ] || continue
  lab=$(basename "$lab_refs")
  manifest="$out/labs/$lab/cases.ini"
  for image in "$lab_refs"*.png; do
    [ -f "$image" ] || continue
    case_name=$(basename "$image" .png)
    if [ ! -f "$manifest" ] || ! grep -q "^\[case $case_name\]" "$manifest"; then
      fail "autograder/references/$lab/$case_name.png is not a public case of labs/$lab/cases.ini (hidden?)"
    fi
  done
  # The recorded render times (the cases' timeouts) name public cases only.
  if [ -f "$lab_refs/render-times.txt" ]; then
    while read -r case_name _; do
      case "$case_name" in ''|'#'*) continue ;; esac
      if [ ! -f "$manifest" ] || ! grep -q "^\[case $case_name\]" "$manifest"; then
        fail "autograder/references/$lab/render-times.txt names $case_name, which is not a public case of labs/$lab/cases.ini (hidden?)"
      fi
    done < "$lab_refs/render-times.txt"
  fi
done

echo "== 3. the docs and comments point only at files the release has"
if command -v python3 >/dev/null 2>&1; then
  if ! python3 "$source/autograder/check-release-paths.py" "$out" > "$out.paths.txt"; then
    while IFS= read -r line; do fail "$line"; done < "$out.paths.txt"
  else
    echo "   $(cat "$out.paths.txt")"
  fi
  rm -f "$out.paths.txt"
else
  echo "   (python3 not found: skipped)"
fi

echo "== 4. configure and build from a clean folder"
build=$(mktemp -d "${TMPDIR:-/tmp}/stoa-release-build.XXXXXX")
start=$(date +%s)
if cmake -S "$out" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "${cmake_args[@]}" > "$build.configure.log" 2>&1 &&
   cmake --build "$build" -j"$jobs" > "$build.build.log" 2>&1; then
  echo "   built in $(( $(date +%s) - start )) s"
  echo "== 5. every case not attempted"
  if ! "$build/bin/stoa-grade" --expect not-attempted --jobs "$jobs" --work-dir "$build/grade"; then
    fail "the release's stoa-grade does not report every case 'not attempted'"
  fi
else
  tail -30 "$build.configure.log" "$build.build.log" >&2 || true
  fail "the release does not build (logs: $build.configure.log, $build.build.log)"
fi

if [ "$failures" -ne 0 ]; then
  echo "make-release: $failures problem(s); the release in $out is NOT ready (build folder kept: $build)" >&2
  exit 1
fi
rm -rf "$build" "$build.configure.log" "$build.build.log"
echo "make-release: $out is ready: $count files, $(du -sh "$out" | cut -f1); it builds and grades as all 'not attempted'"
