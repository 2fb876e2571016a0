#!/bin/sh
# check_sizes.py must name a planted file over 600 lines and a planted function
# over 80 lines, and accept them once they are split.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/framework/src/core"
{
  echo "namespace stoa {"
  echo "int grown(int x) {"
  i=0; while [ $i -lt 85 ]; do echo "    x += $i;"; i=$((i + 1)); done
  echo "    return x;"
  echo "}"
  i=0; while [ $i -lt 600 ]; do echo "// filler $i"; i=$((i + 1)); done
  echo "} // namespace stoa"
} > "$work/framework/src/core/Grown.cpp"
if python3 "$here/check_sizes.py" "$work" > "$work/out.txt"; then
  echo "FAIL: check_sizes.py accepted a 690-line file with an 88-line function"; cat "$work/out.txt"; exit 1
fi
for expected in "framework/src/core/Grown.cpp: over 600 lines" "framework/src/core/Grown.cpp grown: a function over 80 lines"; do
  grep -qF "$expected" "$work/out.txt" || { echo "FAIL: no '$expected' in:"; cat "$work/out.txt"; exit 1; }
done
echo "check_sizes.py names the planted file and function"
