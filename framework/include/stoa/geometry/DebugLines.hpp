#pragma once
// Line segments to show what the renderer otherwise hides: bounding boxes and
// spheres, a camera's frustum (lab 06's overview camera), rays (lab 07). Built
// on the CPU each frame; render/DebugLineRenderer draws them.
//
//   DebugLines lines;
//   lines.box(object.worldBounds().box, {1, 1, 0});
//   lines.sphere(object.worldBounds().sphere, {0, 1, 1});
//   lines.frustum(camera.projection * camera.view, {1, 1, 1});
//   debugRenderer.draw(lines, overview.projection * overview.view);

#include <stoa/geometry/Bounds.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace stoa {

/// One end of a segment, in world space, with its colour (linear RGB).
struct LineVertex {
    glm::vec3 position{0.0f};
    glm::vec3 color{1.0f};
};
static_assert(sizeof(LineVertex) == 6 * sizeof(float), "LineVertex is uploaded as 6 tightly packed floats");

class DebugLines {
public:
    /// The segment from `a` to `b`.
    void line(const glm::vec3& a, const glm::vec3& b, const glm::vec3& color);
    /// The 12 edges of `box`.
    void box(const Aabb& box, const glm::vec3& color);
    /// The 12 edges of `box` (object space) carried by `transform` (an oriented box).
    void box(const Aabb& box, const glm::mat4& transform, const glm::vec3& color);
    /// Three great circles of `sphere`, in the XY, YZ and ZX planes, `segments` segments each (>= 3).
    void sphere(const BoundingSphere& sphere, const glm::vec3& color, int segments = 32);
    /// The 12 edges of the volume that `viewProjection` maps to the clip cube
    /// [-1, 1]^3: a camera's frustum, near plane to far plane.
    void frustum(const glm::mat4& viewProjection, const glm::vec3& color);

    /// Two vertices per segment, in the order they were added.
    const std::vector<LineVertex>& vertices() const { return m_vertices; }
    std::size_t lineCount() const { return m_vertices.size() / 2; }
    /// Forgets every segment (each frame starts empty).
    void clear() { m_vertices.clear(); }

private:
    void edgesOfCorners(const glm::vec3 (&corners)[8], const glm::vec3& color);

    std::vector<LineVertex> m_vertices;
};

} // namespace stoa
