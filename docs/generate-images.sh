#!/usr/bin/env bash
# docs/generate-images.sh [BUILD_DIR] [LAB]   (LAB e.g. 03_meshes: that lab only)
# Renders the pictures the lab pages show, from a solutions build (default
# build-solutions): every case's reference view into docs/images/NN_name/CASE.png
# and every planted mistake, on the first case it fails, into
# docs/images/NN_name/mistakes/MISTAKE.png.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-solutions}
only=${2:-}
[ -d "$build/bin" ] || { echo "generate-images: no $build/bin; build with -DSTOA_USE_SOLUTIONS=ON first" >&2; exit 1; }

for lab_dir in "$root"/labs/[0-9][0-9]_*/; do
  lab=$(basename "$lab_dir")
  [ -z "$only" ] || [ "$lab" = "$only" ] || continue
  program="$build/bin/lab$lab"
  [ -x "$program" ] || continue
  grep -q '^track=solutions$' <("$program" --info) || { echo "generate-images: $program is not a solutions build" >&2; exit 1; }
  out="$root/docs/images/$lab"
  mkdir -p "$out/mistakes"
  for case_name in $("$program" --list); do
    echo "generate-images: $lab/$case_name"
    "$program" --render "$case_name" --output "$out/$case_name.png"
  done
  for mistake_file in "$root"/solutions/"$lab"/mistakes/*.mistake; do
    [ -e "$mistake_file" ] || continue
    mistake=$(basename "$mistake_file" .mistake)
    first_case=$(sed -n 's/^fails:[[:space:]]*\([^[:space:]]*\).*/\1/p' "$mistake_file")
    echo "generate-images: $lab mistake $mistake ($first_case)"
    "$build/bin/mistakes/$lab.$mistake/lab$lab" --render "$first_case" --output "$out/mistakes/$mistake.png"
  done
done
