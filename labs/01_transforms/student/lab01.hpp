#pragma once
// Lab 01: everything you write, in transforms.cpp and cameras.cpp.
// docs/labs/01_transforms.md derives each function.
//
// The framework calls these through its student-code table (StudentCode.hpp),
// which lab 01's program fills at start-up (hand_over.cpp): every object's
// model matrix, every camera's view and projection, and what the cameras do
// with the mouse and keys come from here.
//
// Conventions: right-handed world, column vectors (p' = M p), glm's column-major
// storage (m[column][row]), angles in degrees at this interface.

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace stoa {

// --- transforms.cpp -------------------------------------------------------

/// Object -> world: M = T * Rz * Ry * Rx * S. The object is scaled first, then
/// rotated about X, then Y, then Z (angles in degrees, right-hand rule), then moved
/// to `position`.
glm::mat4 modelMatrix(const glm::vec3& position, const glm::vec3& rotationDegrees, const glm::vec3& scale);

/// World -> view. The camera sits at `eye`, looks at `target`; `up` is any vector
/// not parallel to the view direction. In view space the camera is at the origin
/// looking down -Z with +Y up and +X to the right.
glm::mat4 lookAtMatrix(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up);

/// View -> clip, OpenGL convention: after the divide by w, the visible volume
/// is [-1, 1]^3 with near -> -1 and far -> +1. `fovYDegrees` is the full vertical
/// field of view; `aspect` = width / height; 0 < near < far.
glm::mat4 perspectiveMatrix(float fovYDegrees, float aspect, float near, float far);

// --- cameras.cpp ----------------------------------------------------------
// The orbit camera keeps an OrbitState (target, distance, yaw, pitch), the
// first-person camera a FirstPersonState (position, yaw, pitch); the window
// turns mouse drags and keys into calls of these functions.

/// The orbit camera's eye: the point at `orbit.distance` from `orbit.target`
/// in the direction given by yaw (about +Y; 0 puts the eye on +Z of the
/// target) and pitch (above the target's horizontal plane).
glm::vec3 eyePosition(const OrbitState& orbit);

/// Rotates the eye about the target: yaw += deltaYaw, pitch += deltaPitch,
/// pitch kept in [-89, 89] so the view never flips.
void tumble(OrbitState& orbit, float deltaYawDegrees, float deltaPitchDegrees);

/// Moves the target (and with it the eye) in the view plane: `right` units
/// along the view's right vector, `up` units along its up vector. The view's
/// up is world up (+Y) made perpendicular to the view direction.
void track(OrbitState& orbit, float right, float up);

/// Moves the eye towards the target: distance *= exp(-amount); positive amounts
/// come closer. The distance never drops below 0.05.
void dolly(OrbitState& orbit, float amount);

/// The first-person camera's unit view direction from yaw and pitch (yaw 0,
/// pitch 0 looks down -Z; positive yaw turns left, positive pitch looks up).
glm::vec3 forward(const FirstPersonState& view);

/// Turns the view: yaw += deltaYaw, pitch += deltaPitch, pitch kept in [-89, 89].
void look(FirstPersonState& view, float deltaYawDegrees, float deltaPitchDegrees);

/// Moves the eye by `amount` world units in the camera's frame: x along the
/// horizontal right vector, y along world up, z along the horizontal forward
/// direction (the walk ignores pitch, as in most games).
void move(FirstPersonState& view, const glm::vec3& amount);

} // namespace stoa
