// Lab 01: camera updates. The framework turns mouse drags and keys into calls
// of these functions (framework/src/camera/CameraControls.cpp); you write what
// each call does to the camera's state. Read docs/labs/01_transforms.md, "Cameras".

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

namespace {
constexpr float kMaxPitch = 89.0f;
}

glm::vec3 OrbitCamera::eyePosition() const {
    const float yaw = glm::radians(m_yawDegrees);
    const float pitch = glm::radians(m_pitchDegrees);
    const glm::vec3 offset(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
    return m_target + m_distance * offset;
}

void OrbitCamera::tumble(float deltaYawDegrees, float deltaPitchDegrees) {
    m_yawDegrees += deltaYawDegrees;
    m_pitchDegrees = glm::clamp(m_pitchDegrees + deltaPitchDegrees, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::track(float right, float up) {
    const glm::vec3 back = glm::normalize(eyePosition() - m_target);
    const glm::vec3 rightVector = glm::normalize(glm::cross(upVector(), back));
    const glm::vec3 upVectorOfView = glm::cross(back, rightVector);
    m_target += right * rightVector + up * upVectorOfView;
}

void OrbitCamera::dolly(float amount) { m_distance = std::max(0.05f, m_distance * std::exp(-amount)); }

glm::vec3 FirstPersonCamera::forward() const {
    const float yaw = glm::radians(m_yawDegrees);
    const float pitch = glm::radians(m_pitchDegrees);
    return {-std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

void FirstPersonCamera::look(float deltaYawDegrees, float deltaPitchDegrees) {
    m_yawDegrees += deltaYawDegrees;
    m_pitchDegrees = glm::clamp(m_pitchDegrees + deltaPitchDegrees, -kMaxPitch, kMaxPitch);
}

void FirstPersonCamera::move(const glm::vec3& amount) {
    const float yaw = glm::radians(m_yawDegrees);
    const glm::vec3 walkForward(-std::sin(yaw), 0.0f, -std::cos(yaw));
    const glm::vec3 walkRight(std::cos(yaw), 0.0f, -std::sin(yaw));
    m_position += amount.x * walkRight + amount.y * glm::vec3(0.0f, 1.0f, 0.0f) + amount.z * walkForward;
}

} // namespace stoa
