// Lab 01's functions into the framework's student-code table (StudentCode.hpp):
// the program of every lab that links lab 01's code calls this at start-up.

#include "lab01.hpp"

#include <stoa/core/StudentCode.hpp>

namespace lab01 {

void handOver(stoa::StudentCode& code) {
    code.transforms.modelMatrix = &stoa::modelMatrix;
    code.transforms.lookAtMatrix = &stoa::lookAtMatrix;
    code.transforms.perspectiveMatrix = &stoa::perspectiveMatrix;
    code.cameras.eyePosition = &stoa::eyePosition;
    code.cameras.tumble = &stoa::tumble;
    code.cameras.track = &stoa::track;
    code.cameras.dolly = &stoa::dolly;
    code.cameras.forward = &stoa::forward;
    code.cameras.look = &stoa::look;
    code.cameras.move = &stoa::move;
}

} // namespace lab01
