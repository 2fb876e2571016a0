// stoa/render/FramePass.hpp: a list of passes reads only what was written
// before; the names of targets and sets of them.

#include "catch.hpp"

#include <stoa/render/FramePass.hpp>

#include <stdexcept>
#include <string>

using stoa::FrameTarget;
using stoa::PassSignature;

TEST_CASE("FrameTargets: a set's names in the enum's order, '-' for none", "[render][passes]") {
    CHECK(stoa::toString(stoa::FrameTargets{}) == "-");
    CHECK(stoa::toString(FrameTarget::Output | FrameTarget::GBuffer) == "G-buffer, output");
    const stoa::FrameTargets both = FrameTarget::Levels | FrameTarget::Occlusion;
    CHECK(both.contains(FrameTarget::Levels));
    CHECK_FALSE(both.contains(FrameTarget::GBuffer));
    CHECK(both.containsAll(FrameTarget::Occlusion));
    CHECK(both.without(FrameTarget::Levels) == stoa::FrameTargets(FrameTarget::Occlusion));
}

TEST_CASE("checkPassOrder: each pass reads only what the frame began with or an earlier pass wrote",
          "[render][passes]") {
    const PassSignature geometry{"g-buffer", FrameTarget::Levels, FrameTarget::GBuffer};
    const PassSignature occlusion{"occlusion", FrameTarget::GBuffer, FrameTarget::Occlusion};
    const PassSignature lights{"lights", FrameTarget::GBuffer | FrameTarget::Occlusion, FrameTarget::LightBuffer};

    CHECK_NOTHROW(stoa::checkPassOrder({geometry, occlusion, lights}, FrameTarget::Levels));
    CHECK_NOTHROW(stoa::checkPassOrder({}));

    // The levels are nobody's: the first pass is named, and what it lacks.
    try {
        stoa::checkPassOrder({geometry, occlusion, lights});
        FAIL("a pass that reads what nothing wrote must be refused");
    } catch (const std::logic_error& error) {
        CHECK(std::string(error.what()) == "the pass 'g-buffer' reads levels, which no earlier pass writes");
    }
    // Occlusion after the lights that read it.
    try {
        stoa::checkPassOrder({geometry, lights, occlusion}, FrameTarget::Levels);
        FAIL("a pass before the one that writes what it reads must be refused");
    } catch (const std::logic_error& error) {
        CHECK(std::string(error.what()) == "the pass 'lights' reads occlusion, which no earlier pass writes");
    }
}
