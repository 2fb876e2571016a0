#pragma once
// Lab 07: what you write for ray casting and picking, in rays.cpp and bvh.cpp
// (the ID buffer and the outline are id_buffer.glsl). The app (lab.cpp)
// includes this header; docs/labs/07_picking.md explains
// the math.
//
// The app collects the Acropolis's triangles in world space, builds your BVH
// once (buildBvh), and casts one ray per pixel through it:
//   ray = rayThroughPixel(pixel centre, viewport, inverse(projection * view))
//   hit = intersectBvh(bvh, ray)          // which calls rayHitsBox, rayHitsTriangle

#include <stoa/geometry/Bounds.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace stoa {

/// A ray origin + t direction, t >= 0. inverseDirection is 1 / direction per
/// component (infinite where a component is 0), for the slab test; makeRay()
/// fills it.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    glm::vec3 inverseDirection{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(), -1.0f};
};

/// The ray from `origin` along `direction` (need not be unit length: t is then in its units).
inline Ray makeRay(const glm::vec3& origin, const glm::vec3& direction) {
    return {origin, direction, glm::vec3(1.0f) / direction};
}

/// A triangle in world space, and the object it belongs to (an index into the
/// app's objects).
struct Triangle {
    glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};
    int object = -1;
};

/// The nearest hit found so far: none while triangle < 0.
struct Hit {
    float t = std::numeric_limits<float>::infinity();
    int triangle = -1;   // index into Bvh::triangles
    float u = 0.0f;      // barycentric: the point is (1 - u - v) p0 + u p1 + v p2
    float v = 0.0f;
    bool found() const { return triangle >= 0; }
};

// --- rays.cpp -----------------------------------------------------------

/// The ray from the camera through `pixel` of a `viewport` (pixels from the
/// top-left corner, x right, y down; a pixel's centre is at + 0.5), given the
/// inverse of projection * view: it starts on the near plane and points to the
/// same pixel on the far plane, direction of unit length.
Ray rayThroughPixel(const glm::vec2& pixel, const glm::ivec2& viewport, const glm::mat4& inverseViewProjection);

/// The slab test: true when the ray meets `box` at some t in [0, tMax]; then
/// `tEntry` is where it enters (0 when the origin is inside).
bool rayHitsBox(const Ray& ray, const Aabb& box, float tMax, float& tEntry);

/// Moller and Trumbore (1997): true when the ray meets `triangle` (either side)
/// at a t in (epsilon, hit.t); then hit.t, hit.u and hit.v are set (not
/// hit.triangle: the caller knows which triangle it tested).
bool rayHitsTriangle(const Ray& ray, const Triangle& triangle, Hit& hit);

// --- bvh.cpp ------------------------------------------------------------

/// A node of the tree. A leaf (count > 0) holds triangles first .. first +
/// count - 1 of Bvh::triangles; an inner node (count == 0) has its two
/// children at nodes[first] and nodes[first + 1].
struct BvhNode {
    Aabb box;
    int first = 0;
    int count = 0;
};

/// The deepest a tree may grow (the root is depth 0): the builder makes a node
/// at this depth a leaf, so that a traversal stack of kMaxBvhDepth + 2 entries
/// always suffices.
constexpr int kMaxBvhDepth = 60;

struct Bvh {
    std::vector<Triangle> triangles;   // reordered by the build: each leaf's are contiguous
    std::vector<BvhNode> nodes;        // nodes[0] is the root
};

struct BvhSettings {
    int bins = 12;                 // candidate split planes per axis: bins - 1
    int maxLeafSize = 4;           // a node with more triangles is always split (when it can be)
    float traversalCost = 1.0f;    // C_t: visiting a node
    float intersectionCost = 1.0f; // C_i: testing a triangle
};

/// The surface area heuristic's cost of splitting a node of surface area
/// `parentArea` into children of areas and triangle counts (leftArea,
/// leftCount) and (rightArea, rightCount):
/// C_t + C_i (leftArea leftCount + rightArea rightCount) / parentArea.
float sahSplitCost(float leftArea, int leftCount, float rightArea, int rightCount, float parentArea,
                   const BvhSettings& settings);

/// Builds the tree over `triangles` top-down with binned SAH splits along
/// the triangles' centroids. Every triangle ends up in exactly one leaf.
Bvh buildBvh(std::vector<Triangle> triangles, const BvhSettings& settings = {});

/// The nearest hit of `ray` among the tree's triangles (hit.triangle indexes
/// bvh.triangles), visiting the nearer child first and skipping every node that
/// the ray enters beyond the nearest hit so far.
Hit intersectBvh(const Bvh& bvh, const Ray& ray);

/// The surface area of a box (0 for an empty or inverted one).
inline float surfaceArea(const Aabb& box) {
    const glm::vec3 size = box.max - box.min;
    if (size.x < 0.0f || size.y < 0.0f || size.z < 0.0f) return 0.0f;
    return 2.0f * (size.x * size.y + size.y * size.z + size.z * size.x);
}

} // namespace stoa
