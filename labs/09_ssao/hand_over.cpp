// Lab 09's functions into the framework's student-code table (StudentCode.hpp),
// for CourseRenderer's occlusion: the program of every lab that links lab 09's
// code calls this at start-up.

#include "lab09.hpp"

#include <stoa/core/StudentCode.hpp>
#include <stoa/render/AmbientOcclusion.hpp>

namespace lab09 {

void handOver(stoa::StudentCode& code) {
    code.occlusion.ssaoKernel = &stoa::ssaoKernel;
    code.occlusion.ssaoNoise = &stoa::ssaoNoise;
}

} // namespace lab09
