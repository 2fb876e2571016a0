// Lab 01: camera updates. The window turns mouse drags and keys into calls of
// these functions; you write what each call does to the camera's state (an
// OrbitState or a FirstPersonState, lab01.hpp). Read docs/labs/01_transforms.md, "Cameras".

#include "lab01.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

glm::vec3 eyePosition(const OrbitState& orbit) {
    // TODO(lab01): the point at orbit.distance from orbit.target in the direction given by orbit.yawDegrees and orbit.pitchDegrees.
    (void)orbit;
    throw NotImplemented("eyePosition(OrbitState)");
}

void tumble(OrbitState& orbit, float deltaYawDegrees, float deltaPitchDegrees) {
    // TODO(lab01): change yaw and pitch; keep the pitch in [-89, 89].
    (void)deltaYawDegrees;
    (void)deltaPitchDegrees;
    (void)orbit;
    throw NotImplemented("tumble(OrbitState)");
}

void track(OrbitState& orbit, float right, float up) {
    // TODO(lab01): move the target along the camera's right and up vectors.
    (void)right;
    (void)up;
    (void)orbit;
    throw NotImplemented("track(OrbitState)");
}

void dolly(OrbitState& orbit, float amount) {
    // TODO(lab01): scale the distance by exp(-amount), never below 0.05.
    (void)amount;
    (void)orbit;
    throw NotImplemented("dolly(OrbitState)");
}

glm::vec3 forward(const FirstPersonState& view) {
    // TODO(lab01): the unit view direction for view.yawDegrees and view.pitchDegrees (yaw 0, pitch 0 looks down -Z).
    (void)view;
    throw NotImplemented("forward(FirstPersonState)");
}

void look(FirstPersonState& view, float deltaYawDegrees, float deltaPitchDegrees) {
    // TODO(lab01): change yaw and pitch; keep the pitch in [-89, 89].
    (void)deltaYawDegrees;
    (void)deltaPitchDegrees;
    (void)view;
    throw NotImplemented("look(FirstPersonState)");
}

void move(FirstPersonState& view, const glm::vec3& amount) {
    // TODO(lab01): move view.position by amount.x along the horizontal right vector,
    // amount.y along world up and amount.z along the horizontal forward direction.
    (void)amount;
    (void)view;
    throw NotImplemented("move(FirstPersonState)");
}

} // namespace stoa
