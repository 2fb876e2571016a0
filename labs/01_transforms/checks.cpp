// Lab 01's property checks; see checks.hpp. They drive your cameras far past
// the poles and into the target, and read back the state the cameras keep.

#include "checks.hpp"

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace lab01 {

namespace {

std::string degrees(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", value);
    return text;
}

// Whether `pitch` is the clamp's bound `limit` (±89), allowing float rounding.
bool atLimit(float pitch, float limit) { return std::abs(pitch - limit) < 1e-3f; }

} // namespace

stoa::CheckResult checkCameraLimits() {
    stoa::OrbitCamera orbit(glm::vec3(0.0f), 5.0f, 30.0f, 80.0f);
    orbit.tumble(0.0f, 30.0f);
    if (!atLimit(orbit.pitchDegrees(), 89.0f))
        return stoa::CheckResult::fail("tumble(0, 30) from a pitch of 80 degrees left the orbit camera's pitch at " +
                                       degrees(orbit.pitchDegrees()) +
                                       ": the pitch is clamped to [-89, 89], so the view never flips over the "
                                       "pole (docs: The orbit camera)");
    orbit.tumble(0.0f, -400.0f);
    if (!atLimit(orbit.pitchDegrees(), -89.0f))
        return stoa::CheckResult::fail("tumble(0, -400) left the orbit camera's pitch at " +
                                       degrees(orbit.pitchDegrees()) +
                                       ": the pitch is clamped to [-89, 89] (docs: The orbit camera)");

    stoa::FirstPersonCamera walker(glm::vec3(0.0f, 1.7f, 0.0f), 0.0f, 60.0f);
    walker.look(0.0f, 45.0f);
    if (!atLimit(walker.pitchDegrees(), 89.0f))
        return stoa::CheckResult::fail("look(0, 45) from a pitch of 60 degrees left the first-person camera's pitch at " +
                                       degrees(walker.pitchDegrees()) +
                                       ": the pitch is clamped to [-89, 89], as for the orbit camera "
                                       "(docs: The first-person camera)");
    walker.look(0.0f, -300.0f);
    if (!atLimit(walker.pitchDegrees(), -89.0f))
        return stoa::CheckResult::fail("look(0, -300) left the first-person camera's pitch at " +
                                       degrees(walker.pitchDegrees()) +
                                       ": the pitch is clamped to [-89, 89] (docs: The first-person camera)");

    stoa::OrbitCamera close(glm::vec3(0.0f), 1.0f, 0.0f, 0.0f);
    close.dolly(50.0f);
    if (!(std::fabs(close.distance() - 0.05f) <= 1e-6f))
        return stoa::CheckResult::fail("dolly(50) from a distance of 1 brought the eye to " +
                                       std::to_string(close.distance()) +
                                       " from the target: exp(-50) is far below the floor, so the distance stops at "
                                       "0.05, never below it (docs: The orbit camera)");
    // Above the floor the step is the exponential's alone: exp(-2.5) = 0.082.
    stoa::OrbitCamera nearer(glm::vec3(0.0f), 1.0f, 0.0f, 0.0f);
    nearer.dolly(2.5f);
    if (!(std::fabs(nearer.distance() - std::exp(-2.5f)) <= 1e-5f))
        return stoa::CheckResult::fail("dolly(2.5) from a distance of 1 brought the eye to " +
                                       std::to_string(nearer.distance()) + " from the target; expected exp(-2.5) = " +
                                       std::to_string(std::exp(-2.5f)) +
                                       ", which is above the floor of 0.05 (docs: The orbit camera)");
    return stoa::CheckResult::pass("the pitch stays in [-89, 89] degrees for both cameras, and dolly stops at 0.05");
}

} // namespace lab01
