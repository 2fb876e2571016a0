// Lab 07, part 2: a bounding volume hierarchy over the scene's triangles, built
// with the surface area heuristic, and the nearest hit through it.
// Read docs/labs/07_picking.md, "The BVH", "Where to split" and "Nearest hit"
// first. The app builds the tree once, then asks intersectBvh() for every ray.

#include "lab07.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace stoa {

namespace {

// Helpers you may use (they are not the exercise).

// A box that grows to exactly what is added to it.
[[maybe_unused]] Aabb emptyBox() {
    const float big = std::numeric_limits<float>::max();
    return {glm::vec3(big), glm::vec3(-big)};
}

[[maybe_unused]] void grow(Aabb& box, const glm::vec3& point) {
    box.min = glm::min(box.min, point);
    box.max = glm::max(box.max, point);
}

[[maybe_unused]] void grow(Aabb& box, const Aabb& other) {
    box.min = glm::min(box.min, other.min);
    box.max = glm::max(box.max, other.max);
}

[[maybe_unused]] glm::vec3 centroid(const Triangle& triangle) { return (triangle.p0 + triangle.p1 + triangle.p2) / 3.0f; }

[[maybe_unused]] Aabb boxOf(const Triangle& triangle) {
    Aabb box = emptyBox();
    grow(box, triangle.p0);
    grow(box, triangle.p1);
    grow(box, triangle.p2);
    return box;
}

} // namespace

float sahSplitCost(float leftArea, int leftCount, float rightArea, int rightCount, float parentArea,
                   const BvhSettings& settings) {
    // TODO(lab07): C_t + C_i (A_L N_L + A_R N_R) / A_parent (docs: "Where to split").
    (void)leftArea;
    (void)leftCount;
    (void)rightArea;
    (void)rightCount;
    (void)parentArea;
    (void)settings;
    throw NotImplemented("sahSplitCost()");
}

Bvh buildBvh(std::vector<Triangle> triangles, const BvhSettings& settings) {
    // TODO(lab07): the root holds every triangle in its box; then, for each node
    // (recursively, depth < kMaxBvhDepth):
    //  1. the box of the triangles' centroids; per axis where it has a size,
    //     settings.bins bins of equal width; each triangle into the bin of its
    //     centroid (clamp the last index), growing the bin's box and count;
    //  2. for each of the bins - 1 planes between bins, the boxes and counts left
    //     and right of it (sweep once from each end), and sahSplitCost(); keep
    //     the cheapest plane over all axes;
    //  3. a leaf when no plane has triangles on both sides, or when the node has
    //     at most settings.maxLeafSize triangles and the best cost is not below
    //     the leaf's, C_i * count;
    //  4. otherwise std::partition() the node's triangles by centroid against the
    //     plane, append the two children at nodes[first], nodes[first + 1] (see
    //     BvhNode), and recurse into each (docs: "The BVH", "Where to split").
    (void)triangles;
    (void)settings;
    throw NotImplemented("buildBvh()");
}

Hit intersectBvh(const Bvh& bvh, const Ray& ray) {
    // TODO(lab07): a stack of (node, entry t), starting with the root if the ray
    // meets its box. Pop a node; skip it if it is entered beyond the nearest hit
    // so far; a leaf: rayHitsTriangle() with each of its triangles (set
    // hit.triangle to the index when it returns true); an inner node: push the
    // children whose boxes the ray meets before hit.t, the farther first so that
    // the nearer is visited first (docs: "Nearest hit").
    (void)bvh;
    (void)ray;
    throw NotImplemented("intersectBvh()");
}

} // namespace stoa
