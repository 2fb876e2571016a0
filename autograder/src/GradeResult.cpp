#include "GradeResult.hpp"

namespace stoa::grader {

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

} // namespace stoa::grader
