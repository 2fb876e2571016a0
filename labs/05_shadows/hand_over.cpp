// Lab 05's functions into the framework's student-code table (StudentCode.hpp),
// for ShadowRenderer and CourseRenderer: the program of every lab that links
// lab 05's code calls this at start-up.

#include <stoa/core/StudentCode.hpp>
#include "lab05.hpp"

namespace lab05 {

void handOver(stoa::StudentCode& code) {
    code.shadows.renderShadowPass = &stoa::renderShadowPass;
    code.shadows.cascadeSplits = &stoa::cascadeSplits;
    code.shadows.frustumSliceCorners = &stoa::frustumSliceCorners;
    code.shadows.cascadeLightMatrix = &stoa::cascadeLightMatrix;
}

} // namespace lab05
