#pragma once
// One case of a grading run, from its job to its result: what every mode of
// stoa-grade plans, runs and reports, carried as one value so that a case's job
// and its result are never matched up by position.

#include "CaseRunner.hpp"
#include "GradeResult.hpp"

#include <string>
#include <vector>

namespace stoa::grader {

struct CaseOutcome {
    CaseJob job;
    std::string label;       // put before the case in progress lines ("mistake no_half_vector"); may be empty
    GradeResult result;      // set when the case is graded
    RenderOutcome render;    // set when the case is only rendered (--update-references, --determinism)
};

/// One outcome per job, each with `label`, not yet run.
std::vector<CaseOutcome> plannedOutcomes(std::vector<CaseJob> jobs, const std::string& label = "");

/// The results, in the outcomes' order.
std::vector<GradeResult> resultsOf(const std::vector<CaseOutcome>& outcomes);

} // namespace stoa::grader
