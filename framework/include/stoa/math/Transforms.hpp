#pragma once
// The three matrices every frame is built from. Lab 01 defines them
// (labs/01_transforms/transforms.cpp); docs/labs/01_transforms.md derives them.
// Conventions: right-handed world, column vectors (p' = M p), glm's column-major
// storage (m[column][row]), angles in degrees at this interface.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace stoa {

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

} // namespace stoa
