#include "CaseOutcome.hpp"

namespace stoa::grader {

std::vector<CaseOutcome> plannedOutcomes(std::vector<CaseJob> jobs, const std::string& label) {
    std::vector<CaseOutcome> outcomes;
    outcomes.reserve(jobs.size());
    for (CaseJob& job : jobs) {
        CaseOutcome outcome;
        outcome.result = ungradedResult(job);
        outcome.job = std::move(job);
        outcome.label = label;
        outcomes.push_back(std::move(outcome));
    }
    return outcomes;
}

std::vector<GradeResult> resultsOf(const std::vector<CaseOutcome>& outcomes) {
    std::vector<GradeResult> results;
    results.reserve(outcomes.size());
    for (const CaseOutcome& outcome : outcomes) results.push_back(outcome.result);
    return results;
}

} // namespace stoa::grader
