#include "GradeResult.hpp"

#include <type_traits>
#include <utility>

namespace stoa::grader {

namespace {

// The FLIP mean, where CompareResult has one (it is read through this trait so
// the grader builds against a compare without the perceptual metric too).
template <typename T, typename = void>
struct HasFlipMean : std::false_type {};
template <typename T>
struct HasFlipMean<T, std::void_t<decltype(std::declval<const T&>().flipMean)>> : std::true_type {};

template <typename T>
double flipMeanOf(const T& comparison) {
    if constexpr (HasFlipMean<T>::value)
        return static_cast<double>(comparison.flipMean);
    else
        return -1.0;
}

} // namespace

CompareMetrics metricsOf(const CompareResult& comparison) {
    return CompareMetrics{comparison.badFraction, comparison.meanError, comparison.maxError, flipMeanOf(comparison)};
}

const char* statusName(GradeStatus status) {
    switch (status) {
    case GradeStatus::Passed: return "passed";
    case GradeStatus::Failed: return "failed";
    case GradeStatus::NotAttempted: return "not attempted";
    case GradeStatus::Error: return "error";
    case GradeStatus::NoReference: return "no reference";
    }
    return "unknown";
}

std::optional<GradeStatus> statusFromName(const std::string& name) {
    for (GradeStatus status : kAllStatuses)
        if (name == statusName(status)) return status;
    return std::nullopt;
}

} // namespace stoa::grader
