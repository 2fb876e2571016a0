#!/usr/bin/env bash
# reports_well_formed.sh PYTHON OUT_DIR MISTAKE|- STOA_GRADE [ARGS...]
# Runs STOA_GRADE ARGS with --html, --junit and --json into OUT_DIR, expects it
# to grade (exit 0), and checks the three reports with check_reports.py; with a
# MISTAKE other than '-', a failed case's hint must name it.
set -euo pipefail
python=$1 out=$2 mistake=$3
shift 3
rm -rf "$out"
mkdir -p "$out"
"$@" --html "$out/report.html" --junit "$out/junit.xml" --json "$out/results.json" --work-dir "$out/work"
check=(--mistake "$mistake")
[ "$mistake" = "-" ] && check=()
"$python" "$(dirname "$0")/check_reports.py" "$out/report.html" "$out/junit.xml" "$out/results.json" "${check[@]}"
