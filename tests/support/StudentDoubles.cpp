#include "StudentDoubles.hpp"

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/StudentCode.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace doubles {

namespace {

glm::mat4 model(const glm::vec3& position, const glm::vec3& rotationDegrees, const glm::vec3& scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, glm::radians(rotationDegrees.z), {0.0f, 0.0f, 1.0f});
    m = glm::rotate(m, glm::radians(rotationDegrees.y), {0.0f, 1.0f, 0.0f});
    m = glm::rotate(m, glm::radians(rotationDegrees.x), {1.0f, 0.0f, 0.0f});
    return glm::scale(m, scale);
}

// `ahead` (+Z for the orbit's eye offset, -Z for the walker's view) raised by
// `pitchDegrees` towards +Y, then turned by `yawDegrees` about +Y.
glm::vec3 turned(const glm::vec3& ahead, float yawDegrees, float pitchDegrees) {
    const float raise = ahead.z > 0.0f ? -pitchDegrees : pitchDegrees;   // about +X, right-hand rule
    const glm::mat4 pitch = glm::rotate(glm::mat4(1.0f), glm::radians(raise), {1.0f, 0.0f, 0.0f});
    const glm::mat4 yaw = glm::rotate(glm::mat4(1.0f), glm::radians(yawDegrees), {0.0f, 1.0f, 0.0f});
    return glm::vec3(yaw * pitch * glm::vec4(ahead, 0.0f));
}

float clampedPitch(float degrees) { return std::clamp(degrees, -89.0f, 89.0f); }

} // namespace

void handOverTransformsAndCameras(stoa::StudentCode& code) {
    code.transforms.modelMatrix = &model;
    code.transforms.lookAtMatrix = [](const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
        return glm::lookAt(eye, target, up);
    };
    code.transforms.perspectiveMatrix = [](float fovYDegrees, float aspect, float near, float far) {
        return glm::perspective(glm::radians(fovYDegrees), aspect, near, far);
    };
    code.cameras.eyePosition = [](const stoa::OrbitState& orbit) {
        return orbit.target + orbit.distance * turned({0.0f, 0.0f, 1.0f}, orbit.yawDegrees, orbit.pitchDegrees);
    };
    code.cameras.tumble = [](stoa::OrbitState& orbit, float deltaYaw, float deltaPitch) {
        orbit.yawDegrees += deltaYaw;
        orbit.pitchDegrees = clampedPitch(orbit.pitchDegrees + deltaPitch);
    };
    code.cameras.track = [](stoa::OrbitState& orbit, float right, float up) {
        const glm::mat4 view = glm::lookAt(
            orbit.target + orbit.distance * turned({0.0f, 0.0f, 1.0f}, orbit.yawDegrees, orbit.pitchDegrees),
            orbit.target, {0.0f, 1.0f, 0.0f});
        const glm::mat4 toWorld = glm::inverse(view);
        orbit.target += right * glm::vec3(toWorld[0]) + up * glm::vec3(toWorld[1]);
    };
    code.cameras.dolly = [](stoa::OrbitState& orbit, float amount) {
        orbit.distance = std::max(0.05f, orbit.distance * std::exp(-amount));
    };
    code.cameras.forward = [](const stoa::FirstPersonState& view) {
        return turned({0.0f, 0.0f, -1.0f}, view.yawDegrees, view.pitchDegrees);
    };
    code.cameras.look = [](stoa::FirstPersonState& view, float deltaYaw, float deltaPitch) {
        view.yawDegrees += deltaYaw;
        view.pitchDegrees = clampedPitch(view.pitchDegrees + deltaPitch);
    };
    code.cameras.move = [](stoa::FirstPersonState& view, const glm::vec3& amount) {
        const glm::vec3 ahead = turned({0.0f, 0.0f, -1.0f}, view.yawDegrees, 0.0f);
        const glm::vec3 right = glm::cross(ahead, glm::vec3(0.0f, 1.0f, 0.0f));
        view.position += amount.x * right + amount.y * glm::vec3(0.0f, 1.0f, 0.0f) + amount.z * ahead;
    };
}

} // namespace doubles

namespace {
// Every program that links the doubles starts with them handed over; a test
// that changes an entry does so in a stoa::StudentCodeScope, which puts it back.
[[maybe_unused]] const bool handedOver = (doubles::handOverTransformsAndCameras(stoa::studentCode()), true);
} // namespace
