// Lab 01: camera updates. The framework turns mouse drags and keys into calls
// of these functions (framework/src/camera/CameraControls.cpp); you write what
// each call does to the camera's state. Read docs/labs/01_transforms.md, "Cameras".

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

glm::vec3 OrbitCamera::eyePosition() const {
    // TODO(lab01): the point at m_distance from m_target in the direction given by m_yawDegrees and m_pitchDegrees.
    throw NotImplemented("OrbitCamera::eyePosition()");
}

void OrbitCamera::tumble(float deltaYawDegrees, float deltaPitchDegrees) {
    // TODO(lab01): change yaw and pitch; keep the pitch in [-89, 89].
    (void)deltaYawDegrees;
    (void)deltaPitchDegrees;
    throw NotImplemented("OrbitCamera::tumble()");
}

void OrbitCamera::track(float right, float up) {
    // TODO(lab01): move the target along the camera's right and up vectors.
    (void)right;
    (void)up;
    throw NotImplemented("OrbitCamera::track()");
}

void OrbitCamera::dolly(float amount) {
    // TODO(lab01): scale the distance by exp(-amount), never below 0.05.
    (void)amount;
    throw NotImplemented("OrbitCamera::dolly()");
}

glm::vec3 FirstPersonCamera::forward() const {
    // TODO(lab01): the unit view direction for m_yawDegrees and m_pitchDegrees (yaw 0, pitch 0 looks down -Z).
    throw NotImplemented("FirstPersonCamera::forward()");
}

void FirstPersonCamera::look(float deltaYawDegrees, float deltaPitchDegrees) {
    // TODO(lab01): change yaw and pitch; keep the pitch in [-89, 89].
    (void)deltaYawDegrees;
    (void)deltaPitchDegrees;
    throw NotImplemented("FirstPersonCamera::look()");
}

void FirstPersonCamera::move(const glm::vec3& amount) {
    // TODO(lab01): move m_position by amount.x along the horizontal right vector,
    // amount.y along world up and amount.z along the horizontal forward direction.
    (void)amount;
    throw NotImplemented("FirstPersonCamera::move()");
}

} // namespace stoa
