#pragma once
// `stoa-grade --update-references`: render every selected case with the
// solutions' programs and write autograder/references/<lab>/<case>.png.
//
// It refuses unless every program says `track=solutions` on --info, so a
// student build can never overwrite the references. Per case it prints
//   new        no reference existed; written
//   unchanged  the same pixels, or within the case's tolerance (kept as is, so
//              a CPU's rounding does not churn the repository)
//   changed    beyond the tolerance; rewritten (with the comparison's summary)

#include "CommandLine.hpp"
#include "LabPlan.hpp"

#include <string>

namespace stoa::grader {

/// Returns the exit status: 0 when every reference is written or unchanged, 1 otherwise.
int runUpdateReferences(const Options& options, const Environment& env);

/// The value of the `track=` line of a lab program's --info output ("" when absent).
std::string trackFromInfo(const std::string& infoOutput);

} // namespace stoa::grader
