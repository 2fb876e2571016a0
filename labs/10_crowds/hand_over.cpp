// Lab 10's functions into the framework's student-code table (StudentCode.hpp),
// for CrowdSimulation and CrowdRenderer: the program of every lab that links
// lab 10's code calls this at start-up.

#include "lab10.hpp"

#include <stoa/core/StudentCode.hpp>
#include <stoa/crowd/CrowdLab.hpp>

namespace lab10 {

void handOver(stoa::StudentCode& code) {
    code.crowds.stepStateMachine = &stoa::stepStateMachine;
    code.crowds.arbitrateLayers = &stoa::arbitrateLayers;
    code.crowds.walkableAt = &stoa::walkableAt;
    code.crowds.heightAt = &stoa::heightAt;
    code.crowds.md2FramesAt = &stoa::md2FramesAt;
    code.crowds.blendMd2Frames = &stoa::blendMd2Frames;
}

} // namespace lab10
