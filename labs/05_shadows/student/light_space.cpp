// Lab 05: the light-space matrices, world -> the light's clip space.
// Read docs/labs/05_shadows.md, "The light-space matrix". Your lab-01
// lookAtMatrix() and perspectiveMatrix() do most of the work; glm::ortho
// builds the orthographic projection.

#include "lab01.hpp"

#include <stoa/core/NotImplemented.hpp>
#include "lab05.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace stoa {

glm::mat4 directionalLightMatrix(const glm::vec3& direction, const glm::vec3& sceneMin, const glm::vec3& sceneMax) {
    // TODO(lab05): a view looking along `direction` at the box's centre, then
    // glm::ortho fitted to the extent of the box's eight corners in that view
    // (docs: "The directional light: an orthographic box fitted to the scene").
    (void)direction;
    (void)sceneMin;
    (void)sceneMax;
    throw NotImplemented("directionalLightMatrix()");
}

glm::mat4 spotLightMatrix(const glm::vec3& position, const glm::vec3& target, float fovYDegrees, float near,
                          float far) {
    // TODO(lab05): perspective (square map) times the view from `position` to `target`
    // (docs: "The point light: a perspective frustum").
    (void)position;
    (void)target;
    (void)fovYDegrees;
    (void)near;
    (void)far;
    throw NotImplemented("spotLightMatrix()");
}

} // namespace stoa
