#!/usr/bin/env bash
# One student cannot touch another (issue 30): stoa-grade-class on three
# submissions of lab 01, graded with --jobs 1 and then --jobs 2:
#   aaa_mallory  a correct lab 01 whose transforms.cpp also holds a static
#                initializer that runs in the lab program: it walks /proc for
#                stoa-grade-class, reads its command line and folder, and tries to
#                overwrite every classmate's transforms.cpp with "#error", to read
#                one, and to create SABOTAGED in the grades folder, in each
#                classmate's grades and in solutions/ (whose path it knows, as a
#                student who knows the layout would)
#   mmm_peeker   a correct lab 01 that #includes a classmate's file by absolute path
#   zzz_victim   a correct lab 01
# Checks: the victim and the saboteur keep full marks; the peeker's lab does not
# compile, with a permission error naming the file; every submitted file is
# byte-identical afterwards and none appeared or vanished; no SABOTAGED file
# exists; the gradebook notes no changed submission; no attempt printed
# "sabotage: wrote". Exits 77 (skipped) where the grader says it cannot confine
# files (no Landlock).
#
#   classmates_cannot_touch.sh STOA_GRADE_CLASS SOURCE_DIR WORK_DIR
set -euo pipefail
grade_class=$1 source=$2 work=$3
source=$(cd "$source" && pwd)
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
subs=$work/submissions
make_submission="$(dirname "$0")/make_submission.py"
for student in aaa_mallory mmm_peeker zzz_victim; do
  python3 "$make_submission" "$source" "$subs/$student/labs" > /dev/null
done

# The saboteur, appended to a correct transforms.cpp. It prints one line per attempt.
cat >> "$subs/aaa_mallory/labs/01_transforms/student/transforms.cpp" <<CPP

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

std::string g_sabotageLog;   // also written to sabotage.log in the case folder, the one place it may write

template <typename... Args>
void say(const char* format, Args... args) {
    char line[1024];
    std::snprintf(line, sizeof line, format, args...);
    std::fputs(line, stdout);
    g_sabotageLog += line;
}

std::string sabotageRead(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

void sabotageWrite(const std::string& path, const std::string& text) {
    errno = 0;
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (file << text && file.flush()) say("sabotage: wrote %s\n", path.c_str());
    else say("sabotage: cannot write %s: %s\n", path.c_str(), std::strerror(errno));
}

void sabotage() {
    namespace fs = std::filesystem;
    std::error_code error;
    bool found = false;
    for (const auto& entry : fs::directory_iterator("/proc", error)) {
        std::string cmdline = sabotageRead((entry.path() / "cmdline").string());
        std::vector<std::string> words;
        for (std::size_t at = 0; at < cmdline.size();) {
            std::size_t end = cmdline.find('\0', at);
            if (end == std::string::npos) end = cmdline.size();
            words.push_back(cmdline.substr(at, end - at));
            at = end + 1;
        }
        if (words.empty() || words[0].find("stoa-grade-class") == std::string::npos) continue;
        found = true;
        fs::path cwd = fs::read_symlink(entry.path() / "cwd", error);
        if (error) say("sabotage: cannot read %s/cwd: %s\n", entry.path().c_str(), error.message().c_str());
        fs::path submissions, out;
        for (std::size_t i = 1; i < words.size(); ++i) {
            const std::string& word = words[i];
            if (word == "--out" && i + 1 < words.size()) out = cwd / words[++i];
            else if (word == "--jobs" || word == "--lab" || word == "--timeout" || word == "--framework-build") ++i;
            else if (submissions.empty() && word.rfind("-", 0) != 0) submissions = cwd / word;
        }
        for (const auto& student : fs::directory_iterator(submissions, error)) {
            if (student.path().filename() == "aaa_mallory") continue;
            fs::path victim = student.path() / "labs" / "01_transforms" / "student" / "transforms.cpp";
            std::string text = sabotageRead(victim.string());
            if (text.empty()) say("sabotage: cannot read %s: %s\n", victim.c_str(), std::strerror(errno));
            else say("sabotage: read %zu bytes of %s\n", text.size(), victim.c_str());
            sabotageWrite(victim.string(), "#error sabotaged by a classmate\n");
            if (!out.empty()) sabotageWrite((out / student.path().filename() / "SABOTAGED").string(), "x");
        }
        if (submissions.empty() || error)
            say("sabotage: cannot list the submissions %s: %s\n", submissions.c_str(), error.message().c_str());
        if (!out.empty()) sabotageWrite((out / "SABOTAGED").string(), "x");
    }
    if (!found) say("sabotage: stoa-grade-class not visible in /proc\n");
    sabotageWrite("$source/solutions/01_transforms/SABOTAGED", "x");
    std::ofstream("sabotage.log") << g_sabotageLog;
}

const bool kSabotaged = [] {
    try {
        sabotage();
    } catch (...) {
        say("sabotage: gave up\n");
    }
    std::fflush(stdout);
    return true;
}();

} // namespace
CPP

# The peeker's file includes the victim's by absolute path.
peeker=$subs/mmm_peeker/labs/01_transforms/student/cameras.cpp
{ echo "#include \"$subs/zzz_victim/labs/01_transforms/student/cameras.cpp\""; cat "$peeker"; } > "$peeker.new"
mv "$peeker.new" "$peeker"

record() { (cd "$subs" && find . -type f -print0 | sort -z | xargs -0 sha256sum); }
record > "$work/before.txt"

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

for jobs in 1 2; do
  out=$work/out-jobs$jobs
  echo "== stoa-grade-class --jobs $jobs"
  "$grade_class" "$subs" --out "$out" --lab 01_transforms --jobs "$jobs" > "$work/log-jobs$jobs.txt" 2>&1 || true
  cat "$work/log-jobs$jobs.txt"
  if grep -q "cannot confine the lab programs' files" "$work/log-jobs$jobs.txt"; then
    echo "skipped: this system cannot confine files (no Landlock)"
    exit 77
  fi
  [ -f "$out/gradebook.csv" ] || { fail "--jobs $jobs: no gradebook"; continue; }
  cat "$out/gradebook.csv"
  python3 - "$out/gradebook.csv" "$jobs" <<'PY' || failures=$((failures + 1))
import csv, sys
rows = {row["student"]: row for row in csv.DictReader(open(sys.argv[1]))}
jobs, bad = sys.argv[2], []
for student in ("aaa_mallory", "zzz_victim"):
    row = rows.get(student)
    if not row or row["total"] != row["max"] or row["status"] != "graded":
        bad.append(f"{student} does not have full marks: {row}")
peeker = rows.get("mmm_peeker")
if not peeker or peeker["status"] != "build failed" or "Permission denied" not in peeker["notes"] \
        or "cameras.cpp" not in peeker["notes"]:
    bad.append(f"mmm_peeker's include of a classmate's file is not refused by name: {peeker}")
for student, row in rows.items():
    if "changed during grading" in row["notes"]:
        bad.append(f"{student}'s submission is noted as changed: {row['notes']}")
for line in bad:
    print(f"FAIL: --jobs {jobs}: {line}")
sys.exit(1 if bad else 0)
PY
  record > "$work/after.txt"
  if ! diff "$work/before.txt" "$work/after.txt"; then fail "--jobs $jobs: the submissions changed"; fi
  sabotaged=$( (find "$out" "$source/solutions" -name SABOTAGED 2>/dev/null || true) | sort)
  if [ -n "$sabotaged" ]; then
    fail "--jobs $jobs: files written by the saboteur: $sabotaged"
    # shellcheck disable=SC2086
    rm -f $sabotaged
  fi
  # The saboteur kept a log in its case folders (the one place it may write):
  # it ran, every write failed.
  logs=$(find "$out/aaa_mallory/work" -name sabotage.log 2>/dev/null | sort)
  if [ -z "$logs" ]; then
    fail "--jobs $jobs: the saboteur left no sabotage.log: it did not run"
  else
    first=$(echo "$logs" | head -1)
    echo "-- the saboteur's attempts ($first):"
    cat "$first"
    # shellcheck disable=SC2086
    if grep -h "sabotage: wrote\|sabotage: read [0-9]" $logs; then fail "--jobs $jobs: the saboteur got through (above)"; fi
    # shellcheck disable=SC2086
    grep -q "sabotage: cannot write\|not visible in /proc" $logs ||
      fail "--jobs $jobs: the saboteur's log shows no refused attempt"
  fi
done

if [ "$failures" -ne 0 ]; then
  echo "classmates_cannot_touch: $failures failure(s)"
  exit 1
fi
echo "classmates_cannot_touch: the saboteur changed nothing; its classmates keep full marks"
