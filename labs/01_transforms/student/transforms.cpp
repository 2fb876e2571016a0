// Lab 01: the model, view and projection matrices.
// Read docs/labs/01_transforms.md first. Build your matrices from glm's vector
// operations (glm::cross, glm::dot, glm::normalize, glm::radians, glm::tan) and
// write the entries yourself: glm::lookAt, glm::perspective, glm::translate,
// glm::rotate and glm::scale are what you are reimplementing.
// glm stores matrices column by column: m[c][r] is column c, row r.

#include "lab01.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

glm::mat4 modelMatrix(const glm::vec3& position, const glm::vec3& rotationDegrees, const glm::vec3& scale) {
    // TODO(lab01): return T * Rz * Ry * Rx * S (docs: "The model matrix").
    (void)position;
    (void)rotationDegrees;
    (void)scale;
    throw NotImplemented("modelMatrix()");
}

glm::mat4 lookAtMatrix(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    // TODO(lab01): the camera's basis as rows, and the eye moved to the origin (docs: "The view matrix").
    (void)eye;
    (void)target;
    (void)up;
    throw NotImplemented("lookAtMatrix()");
}

glm::mat4 perspectiveMatrix(float fovYDegrees, float aspect, float near, float far) {
    // TODO(lab01): the OpenGL perspective projection (docs: "The projection matrix").
    (void)fovYDegrees;
    (void)aspect;
    (void)near;
    (void)far;
    throw NotImplemented("perspectiveMatrix()");
}

} // namespace stoa
