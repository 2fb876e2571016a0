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
//
// Then, where the planted mistakes are built, the known-mistake gallery (see
// MistakeGallery.hpp): "gallery: N images".

#include "CaseRunner.hpp"
#include "GradeOptions.hpp"
#include "LabPlan.hpp"

#include <stoa/image/ImageCompare.hpp>

#include <filesystem>

#include <string>

namespace stoa::grader {

/// Writes the render of `render` to `target`, or keeps the image there when it
/// has the same pixels or is within `compare`'s tolerance of it. Returns the line
/// to print ("new", "unchanged ...", "changed (...)", or why not) and sets `ok`.
std::string writeOrKeepImage(const std::filesystem::path& target, const CompareOptions& compare,
                             const RenderOutcome& render, bool& ok);

/// Returns the exit status: 0 when every reference (and gallery image) is
/// written or unchanged, 1 otherwise.
int runUpdateReferences(const Options& options, const Environment& env);

/// The value of the `track=` line of a lab program's --info output ("" when absent).
std::string trackFromInfo(const std::string& infoOutput);

} // namespace stoa::grader
