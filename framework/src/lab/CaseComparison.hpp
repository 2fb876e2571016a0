#pragma once
// The in-window comparison ('g' in a lab's window): the case's picture against
// its reference, as stoa-grade compares them. The reference folder comes from
// the build info (LabBuildInfo::referenceDirectory), so the framework never
// names the grader's folders. Private to framework/src/lab/.

#include <stoa/image/Image.hpp>
#include <stoa/image/ImageCompare.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <filesystem>
#include <string>

namespace stoa::detail {

struct CaseComparison {
    bool haveReference = false;   // false: `problem` says why (no folder, no file, not an image)
    std::string problem;
    Image reference;
    CompareResult result;
    Image difference;             // the heat map, when result.sameSize
};

/// Compares `yours` with `referenceFolder`/<case name>.png under the case's
/// thresholds. An empty folder: no reference.
CaseComparison compareWithReference(const Image& yours, const CaseSpec& spec,
                                    const std::filesystem::path& referenceFolder);

} // namespace stoa::detail
