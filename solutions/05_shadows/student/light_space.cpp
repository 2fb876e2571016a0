// Lab 05: the light-space matrices, world -> the light's clip space.
// Read docs/labs/05_shadows.md, "The light-space matrix". Your lab-01
// lookAtMatrix() and perspectiveMatrix() do most of the work; glm::ortho
// builds the orthographic projection.

#include "lab01.hpp"

#include "lab05.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace stoa {

namespace {

// An up vector not parallel to `direction` (a sun straight overhead has no "up").
glm::vec3 upFor(const glm::vec3& direction) {
    return std::abs(glm::normalize(direction).y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

} // namespace

glm::mat4 directionalLightMatrix(const glm::vec3& direction, const glm::vec3& sceneMin, const glm::vec3& sceneMax) {
    // A view looking along the light from outside the box; any distance works,
    // the projection below is fitted to what the view sees.
    const glm::vec3 center = 0.5f * (sceneMin + sceneMax);
    const float radius = 0.5f * glm::length(sceneMax - sceneMin);
    const glm::vec3 eye = center - glm::normalize(direction) * (2.0f * radius + 1.0f);
    const glm::mat4 view = lookAtMatrix(eye, center, upFor(direction));

    // The box's corners in light view space: their extent is the ortho box.
    glm::vec3 low(INFINITY);
    glm::vec3 high(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 world((corner & 1) ? sceneMax.x : sceneMin.x, (corner & 2) ? sceneMax.y : sceneMin.y,
                              (corner & 4) ? sceneMax.z : sceneMin.z);
        const glm::vec3 lightView = glm::vec3(view * glm::vec4(world, 1.0f));
        low = glm::min(low, lightView);
        high = glm::max(high, lightView);
    }
    // The view looks down -Z: the nearest corner has the largest z. A 1% margin
    // in depth keeps surfaces lying on the box (the floor) off the clip planes.
    const float margin = 0.01f * (high.z - low.z);
    const glm::mat4 projection = glm::ortho(low.x, high.x, low.y, high.y, -high.z - margin, -low.z + margin);
    return projection * view;
}

glm::mat4 spotLightMatrix(const glm::vec3& position, const glm::vec3& target, float fovYDegrees, float near,
                          float far) {
    const glm::mat4 view = lookAtMatrix(position, target, upFor(target - position));
    // A square map: aspect 1.
    return perspectiveMatrix(fovYDegrees, 1.0f, near, far) * view;
}

} // namespace stoa
