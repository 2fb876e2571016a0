#pragma once
// `stoa-grade [--lab ...] [--case ...] ...`: grade, print the report, and
// optionally write Gradescope's results.json.

#include "GradeOptions.hpp"
#include "LabPlan.hpp"

#include <string>
#include <vector>

namespace stoa::grader {

/// Returns the exit status: 0 when grading ran; 1 when nothing could be graded
/// or --expect was not met.
int runGrade(const Options& options, const Environment& env);

/// The lines that say which results break `--expect` (none when all have `expected`).
std::vector<std::string> unmetExpectations(const std::vector<GradeResult>& results, GradeStatus expected);

} // namespace stoa::grader
