#pragma once
// stoa-grade --determinism: renders every selected case four times, twice as
// the grader would and once each with LP_NUM_THREADS=1 and 2 (llvmpipe's
// rasterizer threads), and reports any difference from the first render: bit
// for bit, with the number of differing pixels and the largest channel
// difference. Graded frames must not depend on the run or the thread count.

#include "CaseRunner.hpp"
#include "GradeOptions.hpp"
#include "LabPlan.hpp"

#include <stoa/image/Image.hpp>

#include <string>
#include <vector>

namespace stoa::grader {

/// How two renders of one case differ.
struct ImageDifference {
    bool sameSize = true;
    std::size_t differingPixels = 0;   // pixels with any channel different
    int maxChannelDifference = 0;      // 0..255

    bool identical() const { return sameSize && differingPixels == 0; }
    /// "identical", "37 pixels differ, by at most 2 levels", "sizes differ".
    std::string describe() const;
};

/// Compares two images channel by channel (RGBA; missing channels read as in Image::pixel).
ImageDifference compareExactly(const Image& a, const Image& b);

/// One render of the check: a name ("run 1", "LP_NUM_THREADS=1") and the
/// environment it adds to the lab program's.
struct DeterminismVariant {
    std::string name;
    std::vector<std::string> environment;
};

/// The renders: run 1, run 2 (llvmpipe's default threads, `defaultThreads`),
/// LP_NUM_THREADS=1 and LP_NUM_THREADS=2; the last is left out where the default
/// is 2 threads already (a 2-core machine), as it would repeat runs 1 and 2.
std::vector<DeterminismVariant> determinismVariants(int defaultThreads);

/// The threads llvmpipe renders with when the lab program's environment does not
/// say: $LP_NUM_THREADS, else one per online CPU (0, the calling thread, on one CPU).
int llvmpipeDefaultThreads();

/// Runs the check for the labs and cases `options` selects; prints one line per
/// case and a summary. Returns 0 when every rendered case is identical in every
/// variant, 1 when any differs or fails to render (not-attempted cases are
/// skipped with a note).
int runDeterminismCheck(const Options& options, const Environment& env);

} // namespace stoa::grader
