#pragma once
// `stoa-grade --check-mistakes`: each planted mistake (a solution with one bug,
// built to <bin>/mistakes/<lab>.<mistake>/) must fail the cases its `fails:`
// line names -- fail as "failed", a wrong image, not as an error or "not
// attempted" -- and on at least one of them the known-mistake hint (from the
// gallery, see Hints.hpp) must name that very mistake. Prints one row per
// mistake; exit 1 if any is not caught. Each mistake renders only the cases its
// fails: line names and those its gallery entry records it failing; the others
// count as passed, as they did when the gallery was written (--every-case renders
// them too and names any other case it fails). `--check-hints` likewise renders
// the cases of each fails: line.

#include "GradeOptions.hpp"
#include "GradeResult.hpp"
#include "LabPlan.hpp"
#include "MistakeFile.hpp"

#include <string>
#include <vector>

namespace stoa::grader {

struct MistakeVerdict {
    bool caught = false;
    std::string detail;   // "caught, hint ok", or what went wrong: "orbit_front passed", "fails: names unknown case x"
};

/// Whether `results` (the mistake program's results for its lab) catch `mistake`.
MistakeVerdict judgeMistake(const MistakeFile& mistake, const std::vector<GradeResult>& results);

/// `stoa-grade --check-hints DIR`: whether the results of a mistake kept outside
/// the gallery fail the cases its `fails:` line names, and name no gallery
/// mistake but those its `hint-ok:` line lists (a hint is right or silent).
MistakeVerdict judgeOutOfGallery(const MistakeFile& mistake, const std::vector<GradeResult>& results);

/// With options.outOfGalleryDir, the mistakes outside the gallery instead
/// (judgeOutOfGallery(), programs in <bin>/out-of-gallery/). Returns the exit status: 0 when every built mistake is caught, 1 otherwise
/// (or when there is no mistake program to check).
int runCheckMistakes(const Options& options, const Environment& env);

} // namespace stoa::grader
