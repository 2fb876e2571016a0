#!/usr/bin/env bash
# check_requirements_catches.sh PYTHON SOURCE_DIR WORK_DIR
# check_requirements.py must fail on requirement tables that do not hold: a copy
# of the lab pages, the manifests and the galleries, with one planted problem of each kind.
set -euo pipefail
python=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work/labs" "$work/autograder/references" "$work/solutions"
cp -r "$source/docs" "$work/"
for lab in "$source"/labs/[0-9][0-9]_*/; do
  name=$(basename "$lab")
  mkdir -p "$work/labs/$name"
  cp "$lab/cases.ini" "$work/labs/$name/"
  if [ -d "$source/autograder/references/$name/mistakes" ]; then
    mkdir -p "$work/autograder/references/$name"
    cp -r "$source/autograder/references/$name/mistakes" "$work/autograder/references/$name/"
  fi
  if [ -d "$source/solutions/$name/mistakes" ]; then
    mkdir -p "$work/solutions/$name"
    cp -r "$source/solutions/$name/mistakes" "$work/solutions/$name/"
  fi
done

"$python" "$source/tests/docs/check_requirements.py" "$work" > "$work/clean.txt" ||
  { cat "$work/clean.txt"; echo "FAIL: the unchanged copy does not pass"; exit 1; }

# The planted problems: a row dropped (its mistake then in no row), a case that
# does not exist, a case the row's mistake does not fail, a link to no heading,
# a section that states a rule no row points to, a page without its table.
sed -i '/`radius_longest_row` |$/d' "$work/docs/labs/06_culling.md"
sed -i 's/| `pick_temple_thick_outline` | `outline_plus_not_square` |/| `pick_temple_outline` | `outline_plus_not_square` |/' "$work/docs/labs/07_picking.md"
sed -i 's/| `gbuffer_normals_looking_up` | `fold_by_glsl_sign` |/| `gbuffer_albedo` | `fold_by_glsl_sign` |/' "$work/docs/labs/08_deferred.md"
sed -i 's/| \[The blur\](#the-blur) | `blurred_few_samples`/| [The blur](#the-blurs) | `blurred_few_samples`/' "$work/docs/labs/09_ssao.md"
sed -i 's/<!-- no rule: "never" says which cases/<!-- a comment: "never" says which cases/' "$work/docs/labs/05_shadows.md"
sed -i 's/^## What the grader checks$/## What the grader tests/' "$work/docs/labs/02_shading.md"

status=0
"$python" "$source/tests/docs/check_requirements.py" "$work" > "$work/broken.txt" || status=$?
cat "$work/broken.txt"
[ "$status" -eq 1 ] || { echo "FAIL: check_requirements.py exited with $status on broken tables (expected 1)"; exit 1; }
for expected in "the planted mistake radius_longest_row is in no row" \
                "pick_temple_outline is not a case of labs/07_picking/cases.ini" \
                "no mistake of the row fails gbuffer_albedo" "links to #the-blurs, which is no heading" \
                "section 'Cascaded shadow maps' states a rule" "02_shading.md:0: no '## What the grader checks' section"; do
  grep -qF "$expected" "$work/broken.txt" || { echo "FAIL: no problem reported matching '$expected'"; exit 1; }
done
echo "PASS: every planted problem was reported"
