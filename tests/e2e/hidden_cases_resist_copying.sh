#!/bin/sh
# Hidden cases resist a student who writes out the public reference images.
#   hidden_cases_resist_copying.sh STOA_GRADE SOURCE_DIR WORK_DIR
# For every lab with solutions/NN_name/hidden_cases.ini, a fake lab program
# answers each case with a public reference image: the case's own when there is
# one, else one of the same size (else any). Every public case must pass and
# every hidden case must not.
set -eu
grade=$1
source_dir=$2
work=$3
rm -rf "$work"
mkdir -p "$work/bin"

labs=""
for manifest in "$source_dir"/solutions/*/hidden_cases.ini; do
  [ -f "$manifest" ] || continue
  lab=$(basename "$(dirname "$manifest")")
  labs="$labs $lab"
  cat > "$work/bin/lab$lab" <<SCRIPT
#!/bin/sh
refs="$source_dir/autograder/references/$lab"
case_name=""; output=""; cases="$source_dir/labs/$lab/cases.ini"
while [ \$# -gt 0 ]; do
  case "\$1" in
    --render) case_name=\$2; shift ;;
    --output) output=\$2; shift ;;
    --cases) cases=\$2; shift ;;
  esac
  shift
done
if [ -f "\$refs/\$case_name.png" ]; then cp "\$refs/\$case_name.png" "\$output"; exit 0; fi
# The size the case asks for, from the manifest it came from.
size=\$(awk -v c="[case \$case_name]" '\$0==c {on=1; next} /^\[case / {on=0} on && \$1=="resolution" {print \$3" "\$4}' "\$cases")
pick=""
for ref in "\$refs"/*.png; do
  [ -n "\$pick" ] || pick=\$ref
  dims=\$(od -An -tu1 -j16 -N8 "\$ref" | awk '{print \$3*256+\$4" "\$7*256+\$8}')
  if [ "\$dims" = "\$size" ]; then pick=\$ref; break; fi
done
cp "\$pick" "\$output"
SCRIPT
  chmod +x "$work/bin/lab$lab"
done
if [ -z "$labs" ]; then
  echo "no solutions/*/hidden_cases.ini: nothing to check" >&2
  exit 1
fi

set +e
"$grade" --bin-dir "$work/bin" --work-dir "$work/grade" --jobs 2 > "$work/report.txt" 2> "$work/progress.txt"
set -e
cat "$work/progress.txt"

failures=0
for lab in $labs; do
  public=$(sed -n 's/^\[case \(.*\)\]$/\1/p' "$source_dir/labs/$lab/cases.ini")
  hidden=$(sed -n 's/^\[case \(.*\)\]$/\1/p' "$source_dir/solutions/$lab/hidden_cases.ini")
  for name in $public; do
    if ! grep -q " $lab/$name \.\.\. passed " "$work/progress.txt"; then
      echo "FAIL: the copied public reference of $lab/$name does not pass" >&2
      failures=$((failures + 1))
    fi
  done
  for name in $hidden; do
    if ! grep -q " $lab/$name \.\.\. " "$work/progress.txt"; then
      echo "FAIL: hidden case $lab/$name was not graded" >&2
      failures=$((failures + 1))
    elif grep -q " $lab/$name \.\.\. passed " "$work/progress.txt"; then
      echo "FAIL: hidden case $lab/$name passes with a copied public reference" >&2
      failures=$((failures + 1))
    fi
  done
done
[ "$failures" -eq 0 ] && echo "every public case passed, no hidden case did"
exit "$failures"
