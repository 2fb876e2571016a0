#pragma once
// Lab 06: what you write for culling and level of detail, in bounds.cpp,
// frustum.cpp and level_of_detail.cpp (the sky is skybox.glsl). The app
// (lab.cpp), the benchmark and the tests include this header;
// docs/labs/06_culling.md explains the math.
//
// Every frame the app calls, for each object of the field:
//   sphere  = worldBoundingSphere(meshBoundingSphere(mesh), model)   (the first once per mesh)
//   visible = sphereInFrustum(planes, sphere) && boxInFrustum(planes, worldBox)
//   level   = levelOfDetail(lodQuality(sphere, eye, fovY, height, settings), levels)
// with planes = frustumPlanes(projection * view) once per frame.

#include <stoa/geometry/Bounds.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace stoa {

/// A plane n . p + d = 0. A point p is on the inside (the side the normal
/// points to) when n . p + d >= 0. With |n| = 1, n . p + d is the signed
/// distance of p from the plane.
struct Plane {
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    float d = 0.0f;
};

/// The six planes that bound what a camera sees, normals pointing inwards.
struct Frustum {
    enum Side { Left = 0, Right, Bottom, Top, Near, Far };
    std::array<Plane, 6> planes;
};

// --- bounds.cpp ---------------------------------------------------------

/// The bounding sphere of the mesh's vertex positions, in object space: its
/// centre the centre of their axis-aligned box, its radius the distance from
/// there to the vertex furthest away. A mesh without vertices: centre 0, radius 0.
BoundingSphere meshBoundingSphere(const Mesh& mesh);

/// `sphere` (object space) carried into world space by `model`: the centre
/// transformed as a point, the radius multiplied by the largest factor by which
/// `model` stretches any direction it scales along an axis (the longest of the
/// first three columns), so that the sphere still holds every point of the
/// object under a non-uniform scale.
BoundingSphere worldBoundingSphere(const BoundingSphere& sphere, const glm::mat4& model);

// --- frustum.cpp --------------------------------------------------------

/// The six planes of the frustum that `viewProjection` (world -> clip) maps
/// to the clip cube -w <= x, y, z <= w, in the order of Frustum::Side, each
/// with a unit normal pointing inwards (Gribb and Hartmann 2001).
Frustum frustumPlanes(const glm::mat4& viewProjection);

/// False when the sphere lies wholly on the outside of one of the planes;
/// true otherwise (inside, or crossing a plane). The planes' normals are unit.
bool sphereInFrustum(const Frustum& frustum, const BoundingSphere& sphere);

/// False when the box lies wholly on the outside of one of the planes: for
/// each plane, the box's corner furthest along the normal (the positive
/// vertex) is outside. True otherwise.
bool boxInFrustum(const Frustum& frustum, const Aabb& box);

// --- level_of_detail.cpp ------------------------------------------------

/// When an object gets full detail and when it is not drawn, in pixels of the
/// radius of its bounding sphere on the screen.
struct LodSettings {
    float hiddenBelowPixels = 2.0f;    // a projected radius at or below this: quality 0
    float fullDetailPixels = 80.0f;    // at or above this: quality 1
};

/// The quality factor in [0, 1] of an object whose world-space bounding sphere
/// is `sphere`, seen from `eye` by a perspective camera with a vertical field
/// of view of `fovYDegrees` on a viewport `viewportHeight` pixels tall:
/// the sphere's projected radius in pixels, rho = (height / 2) r / (dist tan(fovY / 2)),
/// mapped linearly from hiddenBelowPixels (0) to fullDetailPixels (1) and
/// clamped. An eye inside the sphere (dist <= r) gets 1.
float lodQuality(const BoundingSphere& sphere, const glm::vec3& eye, float fovYDegrees, int viewportHeight,
                 const LodSettings& settings = {});

/// The level of detail to draw for `quality`, out of `levelCount` levels
/// (0 the full mesh, levelCount - 1 the coarsest): -1 (not drawn) for a
/// quality of 0 or less, else floor((1 - quality) * levelCount), at most levelCount - 1.
int levelOfDetail(float quality, int levelCount);

} // namespace stoa
