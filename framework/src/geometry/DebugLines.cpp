#include <stoa/geometry/DebugLines.hpp>

#include <stoa/core/Assert.hpp>

#include <glm/gtc/constants.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace stoa {

namespace {

// Corner i of a box has x from bit 0, y from bit 1, z from bit 2 (0: min, 1: max).
// The 12 edges join corners that differ in one bit.
constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7},    // along x
                               {0, 2}, {1, 3}, {4, 6}, {5, 7},    // along y
                               {0, 4}, {1, 5}, {2, 6}, {3, 7}};   // along z

glm::vec3 corner(const glm::vec3& low, const glm::vec3& high, int i) {
    return {(i & 1) ? high.x : low.x, (i & 2) ? high.y : low.y, (i & 4) ? high.z : low.z};
}

} // namespace

void DebugLines::line(const glm::vec3& a, const glm::vec3& b, const glm::vec3& color) {
    m_vertices.push_back({a, color});
    m_vertices.push_back({b, color});
}

void DebugLines::edgesOfCorners(const glm::vec3 (&corners)[8], const glm::vec3& color) {
    for (const auto& edge : kEdges) line(corners[edge[0]], corners[edge[1]], color);
}

void DebugLines::box(const Aabb& box, const glm::vec3& color) { this->box(box, glm::mat4(1.0f), color); }

void DebugLines::box(const Aabb& box, const glm::mat4& transform, const glm::vec3& color) {
    glm::vec3 corners[8];
    for (int i = 0; i < 8; ++i) corners[i] = glm::vec3(transform * glm::vec4(corner(box.min, box.max, i), 1.0f));
    edgesOfCorners(corners, color);
}

void DebugLines::sphere(const BoundingSphere& sphere, const glm::vec3& color, int segments) {
    STOA_ASSERT(segments >= 3, "DebugLines::sphere(): a circle needs at least 3 segments");
    const float step = glm::two_pi<float>() / static_cast<float>(segments);
    for (int plane = 0; plane < 3; ++plane) {
        // The circle in the plane of axes (plane, plane + 1).
        auto point = [&](int i) {
            glm::vec3 offset(0.0f);
            offset[plane] = std::cos(step * static_cast<float>(i)) * sphere.radius;
            offset[(plane + 1) % 3] = std::sin(step * static_cast<float>(i)) * sphere.radius;
            return sphere.center + offset;
        };
        for (int i = 0; i < segments; ++i) line(point(i), point(i + 1), color);
    }
}

void DebugLines::frustum(const glm::mat4& viewProjection, const glm::vec3& color) {
    const glm::mat4 inverse = glm::inverse(viewProjection);
    glm::vec3 corners[8];
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 world = inverse * glm::vec4(corner(glm::vec3(-1.0f), glm::vec3(1.0f), i), 1.0f);
        corners[i] = glm::vec3(world) / world.w;
    }
    edgesOfCorners(corners, color);
}

} // namespace stoa
