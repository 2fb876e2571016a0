// Lab 01: camera updates. The window turns mouse drags and keys into calls of
// these functions; you write what each call does to the camera's state (an
// OrbitState or a FirstPersonState, lab01.hpp). Read docs/labs/01_transforms.md, "Cameras".

#include "lab01.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

namespace {
constexpr float kMaxPitch = 89.0f;
}

glm::vec3 eyePosition(const OrbitState& orbit) {
    const float yaw = glm::radians(orbit.yawDegrees);
    const float pitch = glm::radians(orbit.pitchDegrees);
    const glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    return orbit.target + orbit.distance * offset;
}

void tumble(OrbitState& orbit, float deltaYawDegrees, float deltaPitchDegrees) {
    orbit.yawDegrees += deltaYawDegrees;
    orbit.pitchDegrees = glm::clamp(orbit.pitchDegrees + deltaPitchDegrees, -kMaxPitch, kMaxPitch);
}

void track(OrbitState& orbit, float right, float up) {
    const glm::vec3 back = glm::normalize(eyePosition(orbit) - orbit.target);
    const glm::vec3 rightVector = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), back));
    const glm::vec3 upVectorOfView = glm::cross(back, rightVector);
    orbit.target += right * rightVector + up * upVectorOfView;
}

void dolly(OrbitState& orbit, float amount) { orbit.distance = std::max(0.05f, orbit.distance * std::exp(-amount)); }

glm::vec3 forward(const FirstPersonState& view) {
    const float yaw = glm::radians(view.yawDegrees);
    const float pitch = glm::radians(view.pitchDegrees);
    return {-std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

void look(FirstPersonState& view, float deltaYawDegrees, float deltaPitchDegrees) {
    view.yawDegrees += deltaYawDegrees;
    view.pitchDegrees = glm::clamp(view.pitchDegrees + deltaPitchDegrees, -kMaxPitch, kMaxPitch);
}

void move(FirstPersonState& view, const glm::vec3& amount) {
    const float yaw = glm::radians(view.yawDegrees);
    const glm::vec3 walkForward(-std::sin(yaw), 0.0f, -std::cos(yaw));
    const glm::vec3 walkRight(std::cos(yaw), 0.0f, -std::sin(yaw));
    view.position += amount.x * walkRight + amount.y * glm::vec3(0.0f, 1.0f, 0.0f) + amount.z * walkForward;
}

} // namespace stoa
