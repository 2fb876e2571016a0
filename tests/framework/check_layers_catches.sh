#!/bin/sh
# check_layers.py refuses a wrong-way include: a copy of framework/ in which the
# scene layer includes the lab shell's header must fail, naming the file, the
# line and both layers; the copy as it is must pass.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/framework" "$work/framework"
python3 "$here/check_layers.py" "$work/framework" >/dev/null || { echo "FAIL: the copy as it is does not pass"; exit 1; }
target="$work/framework/src/scene/Object.cpp"
sed -i '1i #include <stoa/lab/Lab.hpp>' "$target"
if python3 "$here/check_layers.py" "$work/framework" >"$work/out.txt"; then
  echo "FAIL: a wrong-way include (scene -> lab) passed"; exit 1
fi
grep -q "src/scene/Object.cpp:1: scene (layer [0-9]*) includes <stoa/lab/Lab.hpp> of lab (layer [0-9]*, above it)" "$work/out.txt" ||
  { echo "FAIL: the message does not name the file, the line and the layers:"; cat "$work/out.txt"; exit 1; }
sed -i '1d' "$target"
sed -i '1i #include "../../../labs/01_transforms/student/lab01.hpp"' "$target"
if python3 "$here/check_layers.py" "$work/framework" >"$work/out.txt"; then
  echo "FAIL: an include of a lab's header passed"; exit 1
fi
grep -q "includes nothing outside framework/" "$work/out.txt" || { echo "FAIL:"; cat "$work/out.txt"; exit 1; }
first=$(head -n 1 "$work/out.txt")
sed -i '1d' "$target"
# A GL-free source of stoa_core (the manifests, in the lab shell's area, where
# the layers allow GL) that reaches OpenGL through a header must fail too.
manifest="$work/framework/src/lab/CaseManifest.cpp"
sed -i '1i #include <stoa/gl/Program.hpp>' "$manifest"
if python3 "$here/check_layers.py" "$work/framework" >"$work/out.txt"; then
  echo "FAIL: a stoa_core source that reaches OpenGL passed"; exit 1
fi
grep -q "CaseManifest.cpp: stoa_core reaches OpenGL: CaseManifest.cpp -> stoa/gl/Program.hpp -> " "$work/out.txt" ||
  { echo "FAIL: the message does not show the chain of includes:"; cat "$work/out.txt"; exit 1; }
echo "refused as expected: $first"
echo "refused as expected: $(head -n 1 "$work/out.txt")"
