// Lab 08's functions into the framework's student-code table (StudentCode.hpp),
// for DeferredRenderer: the program of every lab that links lab 08's code
// calls this at start-up.

#include "lab08.hpp"

#include <stoa/core/StudentCode.hpp>
#include <stoa/gl/RenderState.hpp>
#include <stoa/render/DeferredShading.hpp>

namespace lab08 {

void handOver(stoa::StudentCode& code) {
    code.deferred.lightReach = &stoa::lightReach;
    code.deferred.lightVolumeState = &stoa::lightVolumeState;
    code.deferred.buildTileLightLists = &stoa::buildTileLightLists;
}

} // namespace lab08
