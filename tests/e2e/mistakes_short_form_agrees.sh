#!/bin/sh
# stoa-grade --check-mistakes renders each mistake on the cases its fails: line
# names only and counts the others as passed; --every-case renders them all. On
# one lab both must give the same verdict line for every mistake (the same
# hints, and no "also fails": a fails: line lists every case its mistake fails).
# The same for --check-hints on the mistakes outside the gallery, given their folder.
#   mistakes_short_form_agrees.sh STOA_GRADE LAB WORK_DIR [OUT_OF_GALLERY_DIR]
set -eu
grade=$1 lab=$2 work=$3 hints=${4:-}
rm -rf "$work"
mkdir -p "$work"
"$grade" --check-mistakes --lab "$lab" --jobs 2 --work-dir "$work/short" > "$work/short.txt" 2>&1 ||
  { cat "$work/short.txt"; echo "FAIL: --check-mistakes --lab $lab"; exit 1; }
"$grade" --check-mistakes --every-case --lab "$lab" --jobs 2 --work-dir "$work/every" > "$work/every.txt" 2>&1 ||
  { cat "$work/every.txt"; echo "FAIL: --check-mistakes --every-case --lab $lab"; exit 1; }
grep "^$lab\." "$work/short.txt" > "$work/short-verdicts.txt"
grep "^$lab\." "$work/every.txt" > "$work/every-verdicts.txt"
[ -s "$work/short-verdicts.txt" ] || { cat "$work/short.txt"; echo "FAIL: no verdict line for $lab"; exit 1; }
if ! diff "$work/every-verdicts.txt" "$work/short-verdicts.txt"; then
  echo "FAIL: the verdicts differ (< every case, > the fails: cases only)"
  exit 1
fi
short=$(grep -c "^\[" "$work/short.txt" || true)
every=$(grep -c "^\[" "$work/every.txt" || true)
echo "$(wc -l < "$work/short-verdicts.txt") mistakes of $lab: the same verdicts from $short renders as from $every"
[ "$short" -lt "$every" ] || { echo "FAIL: the short form rendered $short cases, not fewer than $every"; exit 1; }

[ -n "$hints" ] || exit 0
"$grade" --check-hints "$hints" --lab "$lab" --jobs 2 --work-dir "$work/hints-short" > "$work/hints-short.txt" 2>&1 ||
  { cat "$work/hints-short.txt"; echo "FAIL: --check-hints --lab $lab"; exit 1; }
"$grade" --check-hints "$hints" --every-case --lab "$lab" --jobs 2 --work-dir "$work/hints-every" \
  > "$work/hints-every.txt" 2>&1 || { cat "$work/hints-every.txt"; echo "FAIL: --check-hints --every-case --lab $lab"; exit 1; }
grep "^$lab\." "$work/hints-short.txt" > "$work/hints-short-verdicts.txt" || true
grep "^$lab\." "$work/hints-every.txt" > "$work/hints-every-verdicts.txt" || true
[ -s "$work/hints-short-verdicts.txt" ] || { cat "$work/hints-short.txt"; echo "FAIL: no --check-hints verdict for $lab"; exit 1; }
if ! diff "$work/hints-every-verdicts.txt" "$work/hints-short-verdicts.txt"; then
  echo "FAIL: the --check-hints verdicts differ (< every case, > the fails: cases only)"
  exit 1
fi
echo "$(wc -l < "$work/hints-short-verdicts.txt") mistakes of $lab outside the gallery: the same verdicts"
