#pragma once
// How long each case may run, from how long the solution takes to render it.
//
// `stoa-grade --update-references` records each case's render time beside its
// reference image, in <references folder>/render-times.txt:
//
//   # case  seconds (the solution's render, rounded up to a tenth)
//   orbit_front 0.4
//
// A case then gets max(kTimeoutFloorSeconds, kTimeoutFactor x that time) before its
// lab program is killed. Once a program has timed out it may hang, and its
// remaining cases get max(kShortTimeoutFloorSeconds, kShortTimeoutFactor x the
// time), so that a hanging lab costs seconds, not a minute per case; after
// kMaxTimeoutsInARow timeouts under the short limit in a row (a case that
// finishes in time ends the streak), its remaining cases are not run. A hanging
// lab thus costs at most 15 + 3 x 4 s with one job (the default), less with more. The floor of the short
// limit leaves a correct case room on a loaded machine (lab 07's id_buffer, 0.5 s
// recorded, took 3 s there). Builds with
// AddressSanitizer multiply both by kSanitizerSlowdown. A case with no recorded time
// gets kUnrecordedTimeoutSeconds. `--timeout SECONDS` replaces all of this with one
// limit for every case. The margins are in docs/instructor-guide.md, "Timeouts".

#include <filesystem>
#include <map>
#include <string>

namespace stoa::grader {

constexpr double kTimeoutFloorSeconds = 15.0;
constexpr double kTimeoutFactor = 10.0;
constexpr double kShortTimeoutFloorSeconds = 4.0;
constexpr double kShortTimeoutFactor = 3.0;
constexpr double kUnrecordedTimeoutSeconds = 30.0;
constexpr double kSanitizerSlowdown = 4.0;
constexpr int kMaxTimeoutsInARow = 3;

struct CaseTimeouts {
    double first = kUnrecordedTimeoutSeconds;          // the case's limit
    double afterTimeout = kShortTimeoutFloorSeconds;   // its limit once its program has timed out
};

/// The limits for a case whose solution renders in `referenceSeconds` (0: not
/// recorded); `sanitized` for a build with AddressSanitizer.
CaseTimeouts caseTimeouts(double referenceSeconds, bool sanitized);

/// <references folder>/render-times.txt
std::filesystem::path renderTimesPath(const std::filesystem::path& referencesFolder);

/// The recorded times by case name; empty when the file does not exist. Throws
/// InputError naming the file and line for a line that is not "name seconds".
std::map<std::string, double> readRenderTimes(const std::filesystem::path& file);

/// Records `measured` (case -> seconds) into `file`, keeping the other cases'
/// lines. A case's recorded time changes only when the new one is more than twice
/// or less than half of it, so that a machine's noise does not churn the
/// repository. Returns true when the file was written.
bool updateRenderTimes(const std::filesystem::path& file, const std::map<std::string, double>& measured);

} // namespace stoa::grader
