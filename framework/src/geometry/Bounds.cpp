#include <stoa/geometry/Bounds.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

bool Aabb::contains(const glm::vec3& point) const {
    return glm::all(glm::greaterThanEqual(point, min)) && glm::all(glm::lessThanEqual(point, max));
}

Bounds boundsOf(const Mesh& mesh) {
    Bounds bounds;
    if (mesh.vertices.empty()) return bounds;
    const auto [low, high] = mesh.bounds();
    bounds.box = {low, high};
    bounds.sphere.center = bounds.box.center();
    float radiusSquared = 0.0f;
    for (const Vertex& vertex : mesh.vertices) {
        const glm::vec3 offset = vertex.position - bounds.sphere.center;
        radiusSquared = std::max(radiusSquared, glm::dot(offset, offset));
    }
    bounds.sphere.radius = std::sqrt(radiusSquared);
    return bounds;
}

Bounds transformed(const Bounds& bounds, const glm::mat4& transform) {
    // Arvo (1990): each output axis is the translation plus, for each input
    // axis, the smaller and the larger of the two products with min and max.
    Bounds result;
    const glm::vec3 translation(transform[3]);
    result.box.min = result.box.max = translation;
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row) {
            const float a = transform[column][row] * bounds.box.min[column];
            const float b = transform[column][row] * bounds.box.max[column];
            result.box.min[row] += std::min(a, b);
            result.box.max[row] += std::max(a, b);
        }
    const float scale = std::max({glm::length(glm::vec3(transform[0])), glm::length(glm::vec3(transform[1])),
                                  glm::length(glm::vec3(transform[2]))});
    result.sphere.center = glm::vec3(transform * glm::vec4(bounds.sphere.center, 1.0f));
    result.sphere.radius = bounds.sphere.radius * scale;
    return result;
}

} // namespace stoa
