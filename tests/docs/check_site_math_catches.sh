#!/usr/bin/env bash
# check_site_math_catches.sh PYTHON SITE_DIR SOURCE_DIR WORK_DIR
# check_site_math.py must fail on a site whose equations would not reach the reader: a copy of
# the built site and of docs/, with one planted problem of each kind.
set -euo pipefail
python=$1 site=$2 source=$3 work=$4
rm -rf "$work"
mkdir -p "$work/source"
cp -r "$site" "$work/site"
cp -r "$source/docs" "$work/source/"

"$python" "$source/tests/docs/check_site_math.py" "$work/site" "$work/source" > "$work/clean.txt" ||
  { cat "$work/clean.txt"; echo "FAIL: the unchanged copy does not pass"; exit 1; }

# The planted problems.
sed -i '0,/<\/h1>/s//<\/h1><p>left raw: $$I_{out}$$<\/p>/' "$work/site/labs/02_shading/index.html"
rm "$work/site/mathjax/jax/output/CommonHTML/autoload/mtable.js"
sed -i 's|</head>|<script src="https://cdn.example.org/mathjax.js"></script></head>|' "$work/site/index.html"
printf '\nA thin space: $a \\, b$.\n\nA hat: $\\hat{A}_1 = B_{1}$.\n' >> "$work/source/docs/labs/03_meshes.md"

status=0
"$python" "$source/tests/docs/check_site_math.py" "$work/site" "$work/source" > "$work/broken.txt" || status=$?
cat "$work/broken.txt"
[ "$status" -eq 1 ] || { echo "FAIL: check_site_math.py exited with $status on a broken site (expected 1)"; exit 1; }
for expected in 'labs/02_shading/index.html:' 'raw $$ in the text' 'autoload/mtable.js: missing' \
                'index.html:' 'loads https://cdn.example.org/mathjax.js from the network' \
                'docs/labs/03_meshes.md:' '\, in an equation' 'the _ pair in ... A hat: $\hat{A}_1 = B_{1}$'; do
  grep -qF "$expected" "$work/broken.txt" || { echo "FAIL: no problem reported matching '$expected'"; exit 1; }
done
echo "PASS: every planted problem was reported"
