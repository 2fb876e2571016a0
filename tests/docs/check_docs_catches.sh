#!/usr/bin/env bash
# check_docs_catches.sh PYTHON SOURCE_DIR WORK_DIR
# check_docs.py must fail on docs that do not hold together: a copy of the docs,
# the manifests and the galleries, with one planted problem of each kind.
set -euo pipefail
python=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work/labs" "$work/autograder/references"
cp -r "$source/docs" "$source/mkdocs.yml" "$work/"
for lab in "$source"/labs/[0-9][0-9]_*/; do
  name=$(basename "$lab")
  mkdir -p "$work/labs/$name"
  cp "$lab/cases.ini" "$work/labs/$name/"
  # The reference pictures the pages show, and the galleries.
  if [ -d "$source/autograder/references/$name" ]; then
    cp -r "$source/autograder/references/$name" "$work/autograder/references/"
  fi
done

"$python" "$source/tests/docs/check_docs.py" "$work" > "$work/clean.txt" ||
  { cat "$work/clean.txt"; echo "FAIL: the unchanged copy does not pass"; exit 1; }

# The planted problems.
printf '\nAs seed 002 shows, and as Blinn (1979) wrote.\n' >> "$work/docs/labs/02_shading.md"
sed -i 's/Fails: `pcf_3x3`/Fails: `pcf_2x2`/' "$work/docs/labs/05_shadows.md"
sed -i 's/!\[Reference picture of case orbit_front\]/![Reference picture of case wide_lens]/' "$work/docs/labs/01_transforms.md"
sed -i '/References: references.md/d' "$work/mkdocs.yml"
rm "$work/autograder/references/02_shading/sun.png"

status=0
"$python" "$source/tests/docs/check_docs.py" "$work" > "$work/broken.txt" || status=$?
cat "$work/broken.txt"
[ "$status" -eq 1 ] || { echo "FAIL: check_docs.py exited with $status on broken docs (expected 1)"; exit 1; }
for expected in "a source named by a label" "cites Blinn (1979)" "says mistake pcf_offsets_not_texels fails pcf_2x2" \
                "the caption says case wide_lens but the picture is orbit_front.png" "not in the site's nav" \
                "autograder/references/02_shading/sun.png does not exist"; do
  grep -qF "$expected" "$work/broken.txt" || { echo "FAIL: no problem reported matching '$expected'"; exit 1; }
done
echo "PASS: every planted problem was reported"
