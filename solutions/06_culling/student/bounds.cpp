// Lab 06, part 1: bounding spheres, in object space and in world space.
// Read docs/labs/06_culling.md, "Bounding volumes", first. The app computes a
// mesh's sphere once, then carries it into world space for every object that
// uses the mesh, every frame: the culling tests and the level of detail use
// only this sphere (and the framework's world box).

#include "lab06.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

BoundingSphere meshBoundingSphere(const Mesh& mesh) {
    BoundingSphere sphere;
    if (mesh.vertices.empty()) return sphere;
    glm::vec3 low = mesh.vertices.front().position;
    glm::vec3 high = low;
    for (const Vertex& vertex : mesh.vertices) {
        low = glm::min(low, vertex.position);
        high = glm::max(high, vertex.position);
    }
    sphere.center = 0.5f * (low + high);
    float farthestSquared = 0.0f;
    for (const Vertex& vertex : mesh.vertices) {
        const glm::vec3 offset = vertex.position - sphere.center;
        farthestSquared = std::max(farthestSquared, glm::dot(offset, offset));
    }
    sphere.radius = std::sqrt(farthestSquared);
    return sphere;
}

BoundingSphere worldBoundingSphere(const BoundingSphere& sphere, const glm::mat4& model) {
    // A unit step along object axis i moves by column i of the upper 3x3: no
    // direction is stretched more than the longest column (for a rotation
    // times a scale; a shear could stretch a diagonal more, and the framework
    // makes none).
    const float scale = std::max({glm::length(glm::vec3(model[0])), glm::length(glm::vec3(model[1])),
                                  glm::length(glm::vec3(model[2]))});
    return {glm::vec3(model * glm::vec4(sphere.center, 1.0f)), sphere.radius * scale};
}

} // namespace stoa
