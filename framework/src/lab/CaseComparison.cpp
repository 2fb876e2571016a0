#include "CaseComparison.hpp"

#include <stoa/core/InputError.hpp>

namespace stoa::detail {

CaseComparison compareWithReference(const Image& yours, const CaseSpec& spec,
                                    const std::filesystem::path& referenceFolder) {
    CaseComparison comparison;
    if (referenceFolder.empty()) {
        comparison.problem = "this program was built without a reference folder";
        return comparison;
    }
    try {
        comparison.reference = Image::load(referenceFolder / (spec.name + ".png"));
    } catch (const InputError& error) {
        comparison.problem = error.what();
        return comparison;
    }
    comparison.haveReference = true;
    comparison.result = compareImages(yours, comparison.reference, spec.compare);
    if (comparison.result.sameSize)
        comparison.difference = differenceHeatMap(yours, comparison.reference, comparison.result, spec.compare);
    return comparison;
}

} // namespace stoa::detail
