// Lab 01's property checks; see checks.hpp. They drive your cameras far past
// the poles and into the target, and read back the state the cameras keep.

#include "checks.hpp"
#include "lab01.hpp"

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>

#include <glm/glm.hpp>

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

stoa::CheckResult checkMatricesMapTheFrustum() {
    // The projection: the near and far planes to NDC z = -1 and +1, the edges of
    // the field of view to x, y = +-1, for a lens none of the cases uses.
    const float fovY = 50.0f, aspect = 1.6f, near = 0.3f, far = 70.0f;
    const glm::mat4 projection = stoa::perspectiveMatrix(fovY, aspect, near, far);
    const float tangent = std::tan(glm::radians(fovY) * 0.5f);
    struct Landing {
        glm::vec3 view;   // a view-space point
        int axis;         // which NDC coordinate is checked
        float ndc;        // where it must land
        const char* what;
    };
    const Landing landings[] = {
        {{0.0f, 0.0f, -near}, 2, -1.0f, "a point on the near plane"},
        {{0.0f, 0.0f, -far}, 2, 1.0f, "a point on the far plane"},
        {{0.0f, 0.0f, -2.0f * near}, 2, near / (far - near), "a point at twice the near distance"},
        {{0.0f, 5.0f * tangent, -5.0f}, 1, 1.0f, "a point on the top edge of the field of view"},
        {{-5.0f * tangent * aspect, 0.0f, -5.0f}, 0, -1.0f, "a point on the left edge"},
    };
    for (const Landing& landing : landings) {
        const glm::vec4 clip = projection * glm::vec4(landing.view, 1.0f);
        const float got = clip[landing.axis] / clip.w;
        if (!(std::abs(got - landing.ndc) <= 1e-3f))
            return stoa::CheckResult::fail("perspectiveMatrix(50, 1.6, 0.3, 70) takes " + std::string(landing.what) + ", " +
                                           stoa::checkVector(landing.view) + ", to NDC " + std::string("xyz").substr(landing.axis, 1) +
                                           " = " + stoa::checkNumber(got, 4) + "; expected " +
                                           stoa::checkNumber(landing.ndc, 4) + " (docs: The projection matrix)");
    }
    // The view: the eye to the origin, the target straight ahead on -Z, and w kept.
    const glm::vec3 eye(3.0f, 2.0f, 5.0f), target(-1.0f, 0.5f, -2.0f);
    const glm::mat4 view = stoa::lookAtMatrix(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec4 eyeView = view * glm::vec4(eye, 1.0f), targetView = view * glm::vec4(target, 1.0f);
    const float distance = glm::length(target - eye);
    if (glm::length(glm::vec3(eyeView)) > 1e-4f || std::abs(eyeView.w - 1.0f) > 1e-6f ||
        glm::length(glm::vec3(targetView) - glm::vec3(0.0f, 0.0f, -distance)) > 1e-4f || std::abs(targetView.w - 1.0f) > 1e-6f)
        return stoa::CheckResult::fail("lookAtMatrix() from " + stoa::checkVector(eye) + " towards " + stoa::checkVector(target) +
                                       " takes the eye to " + stoa::checkVector(glm::vec3(eyeView)) + " (w " +
                                       stoa::checkNumber(eyeView.w, 3) + ") and the target to " +
                                       stoa::checkVector(glm::vec3(targetView)) + " (w " + stoa::checkNumber(targetView.w, 3) +
                                       "); expected the origin and (0, 0, -" + stoa::checkNumber(distance, 3) +
                                       "), w 1: the last row is (0, 0, 0, 1) (docs: The view matrix)");
    return stoa::CheckResult::pass("perspectiveMatrix() takes the near and far planes to -1 and 1 and the edges of the "
                                   "field of view to +-1; lookAtMatrix() takes the eye to the origin and the target "
                                   "down -Z, w kept");
}

} // namespace lab01
