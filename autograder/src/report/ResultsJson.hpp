#pragma once
// Gradescope's results.json (https://gradescope-autograders.readthedocs.io/en/latest/specs/):
//
//   { "score": 15, "execution_time": 42, "output": "...", "visibility": "visible",
//     "stdout_visibility": "hidden",
//     "tests": [ { "score": 10, "max_score": 10, "status": "passed",
//                  "name": "01_transforms/orbit_front", "number": "1.1",
//                  "output": "...", "tags": ["01_transforms"], "visibility": "visible",
//                  "extra_data": { "render_seconds": 0.8, "hint_mistake": "...", "hint_docs": "..." } },
//                ... ] }
//
// Only keys the specification documents are written: it has execution_time at
// the top level only (whole seconds), so a case's render time goes in its
// extra_data, as do the known-mistake hint's name and docs path (the hint's
// text is in the case's output, where students see it). Hidden cases get the
// visibility "after_published": students see them once the instructor
// publishes the grades. The grader's own stdout stays hidden from students.

#include "GradeResult.hpp"
#include "Report.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

/// The document as text. `executionSeconds` is the whole run's wall-clock time;
/// `output` is shown to the student above the tests (the score line and hints).
std::string resultsJson(const std::vector<GradeResult>& results, const Totals& totals, double executionSeconds,
                        const std::string& output);

/// Writes resultsJson() to `path` (its folder is created). Throws InputError when it cannot.
void writeResultsJson(const std::filesystem::path& path, const std::vector<GradeResult>& results,
                      const Totals& totals, double executionSeconds, const std::string& output);

} // namespace stoa::grader
