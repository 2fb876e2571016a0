#!/usr/bin/env bash
# Packages the Gradescope autograder: a zip with setup.sh and run_autograder at its
# root (autograder/gradescope/) and the student release of this tree in stoa/.
#
#   autograder/make-gradescope-package.sh OUT.zip [--with-hidden]
#
# --with-hidden adds solutions/ (hidden cases and their references, which are
# graded only where solutions exist); the package is never shown to students, but
# their code runs beside it, so leave it out unless the hidden cases are wanted.
# Upload OUT.zip in Gradescope: Assignment -> Configure Autograder -> Zip file upload.
set -euo pipefail
out="" hidden=0
for argument in "$@"; do
  case "$argument" in
    --with-hidden) hidden=1 ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "make-gradescope-package: unknown option $argument" >&2; exit 2 ;;
    *) [ -z "$out" ] || { echo "make-gradescope-package: one OUT.zip, please" >&2; exit 2; }; out=$argument ;;
  esac
done
case "$out" in *.zip) ;; *) echo "usage: autograder/make-gradescope-package.sh OUT.zip [--with-hidden]" >&2; exit 2 ;; esac
command -v zip >/dev/null || { echo "make-gradescope-package: needs zip (run .ci/install-deps.sh)" >&2; exit 1; }

source=$(cd "$(dirname "$0")/.." && pwd)
stage=$(mktemp -d "${TMPDIR:-/tmp}/stoa-gradescope.XXXXXX")
trap 'rm -rf "$stage"' EXIT
"$source/autograder/make-release.sh" "$stage/stoa" --no-verify
if [ "$hidden" = 1 ]; then
  [ -d "$source/solutions" ] || { echo "make-gradescope-package: --with-hidden, but this tree has no solutions/" >&2; exit 1; }
  cp -r "$source/solutions" "$stage/stoa/solutions"
fi
cp "$source/autograder/gradescope/setup.sh" "$source/autograder/gradescope/run_autograder" "$stage/"
mkdir -p "$(dirname "$out")"
out=$(cd "$(dirname "$out")" && pwd)/$(basename "$out")
rm -f "$out"
(cd "$stage" && zip -q -r "$out" setup.sh run_autograder stoa)
echo "make-gradescope-package: wrote $out ($(du -h "$out" | cut -f1)$([ "$hidden" = 1 ] && echo ', with solutions/ for the hidden cases'))"
