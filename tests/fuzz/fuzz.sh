#!/usr/bin/env bash
# Fuzzes each loader for a given time, one after the other, one process each.
#   tests/fuzz/fuzz.sh [MINUTES_PER_LOADER] [obj|image|heightmap|md2|crowd_xml|editor_scene|sound ...]
# Default: 10 minutes each for obj, image, heightmap, md2, crowd_xml, editor_scene and sound. Builds the fuzzers
# (build-fuzzers.sh) and the corpora (make-regression-corpus.py) in
# $FUZZ_OUT (default build-fuzz), keeps each loader's growing corpus in
# $FUZZ_OUT/work/LOADER and its log in $FUZZ_OUT/LOADER.log, and writes any
# crashing, leaking, slow (> 1 s) or memory-hungry input to
# $FUZZ_OUT/findings/LOADER/. A finding is fixed, then added to the
# regression corpus (make-regression-corpus.py, or tests/fuzz/findings/).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
minutes=${1:-10}
shift || true
targets=("$@")
(( ${#targets[@]} )) || targets=(obj image heightmap md2 crowd_xml editor_scene sound)
out=${FUZZ_OUT:-$root/build-fuzz}
rss_mb=${FUZZ_RSS_MB:-2048}

"$root/tests/fuzz/build-fuzzers.sh" "$out"
python3 "$root/tests/fuzz/make-regression-corpus.py" "$out/corpus"
status=0
for target in "${targets[@]}"; do
  kind=$target
  [[ $target == heightmap ]] && kind=image
  mkdir -p "$out/work/$target" "$out/findings/$target"
  # Seeds and the small regression files start the corpus (the 100,000-corner OBJ
  # files and the 28 KB JPGs are for the replay: under ASan a run of one takes long
  # enough on a loaded machine to pass -timeout=1).
  cp -n "$out/corpus/seeds/$kind"/* "$out/work/$target/"
  find "$out/corpus/regression/$kind" -type f -size -8k -exec cp -n {} "$out/work/$target/" \;
  if [[ -d "$root/tests/fuzz/findings/$kind" ]]; then cp -n "$root/tests/fuzz/findings/$kind"/* "$out/work/$target/" 2>/dev/null || true; fi
  echo "== fuzzing $target for $minutes min (log: $out/$target.log)"
  # A text format's names (tests/fuzz/TARGET.dict) let mutations past "unknown element".
  dict=()
  [[ -f "$root/tests/fuzz/$target.dict" ]] && dict=("-dict=$root/tests/fuzz/$target.dict")
  # -fork=1: one worker process at a time, restarted after a finding, so that
  # one slow input does not end the run: on a shared machine (nice -n 19) a
  # run can stall past -timeout=1 for want of a CPU. Every timeout is then
  # replayed alone below; one that is slow again is a finding.
  nice -n 19 "$out/fuzz-$target" "$out/work/$target" "${dict[@]}" -fork=1 -ignore_timeouts=1 \
       -max_total_time=$((minutes * 60)) -timeout=1 -rss_limit_mb="$rss_mb" -malloc_limit_mb="$rss_mb" \
       -max_len=8192 -print_final_stats=1 -artifact_prefix="$out/findings/$target/" >"$out/$target.log" 2>&1 || status=1
  grep -E '^#[0-9]+: cov:' "$out/$target.log" | tail -1 || true
  for unit in "$out/findings/$target"/timeout-*; do
    [[ -e $unit ]] || continue
    if "$out/fuzz-$target" -timeout=1 -runs=5 "$unit" >/dev/null 2>&1; then
      mkdir -p "$out/findings/$target/load-stalls"
      mv "$unit" "$out/findings/$target/load-stalls/"
      echo "   $(basename "$unit"): under 1 s when replayed alone (a stall of the loaded machine, kept in load-stalls/)"
    else
      echo "   $(basename "$unit"): slow again when replayed alone: a finding"
      status=1
    fi
  done
  for unit in "$out/findings/$target"/{crash,leak,oom,slow-unit}-*; do
    [[ -e $unit ]] && { echo "   finding: $unit"; status=1; }
  done
done
exit $status
