#pragma once
// Bounding volumes: what culling tests against (lab 06) and what fits a shadow
// map's box. Every mesh knows its bounds in object space (GpuMesh::bounds());
// an object carries them into world space through its model matrix
// (Object::worldBounds()). No OpenGL here.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace stoa {

class Mesh;

/// An axis-aligned box, min <= max on every axis.
struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};

    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return max - min; }
    bool contains(const glm::vec3& point) const;
};

struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;   // >= 0
};

/// The two volumes of one thing, in one space (object or world, as the
/// function that returns them says).
struct Bounds {
    Aabb box;
    BoundingSphere sphere;
};

/// The bounds of the mesh's vertex positions, in object space: the tight box,
/// and a sphere about the box's centre through the vertex furthest from it.
/// A mesh without vertices has empty bounds at the origin.
Bounds boundsOf(const Mesh& mesh);

/// `bounds` carried by `transform` (object -> world, say): the box that holds
/// the transformed box (Arvo's method, exact for the box's corners), and the
/// sphere about the transformed centre, its radius scaled by the transform's
/// largest axis scale (so it holds every transformed point for any affine
/// transform).
Bounds transformed(const Bounds& bounds, const glm::mat4& transform);

} // namespace stoa
