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

struct Split {
    int axis = -1;      // -1: no split is better than a leaf
    float position = 0.0f;
    float cost = std::numeric_limits<float>::max();
};

// The best of the bins - 1 planes per axis between the bins of the centroids.
Split bestSplit(const Bvh& bvh, const BvhNode& node, const BvhSettings& settings) {
    Aabb centroids = emptyBox();
    for (int i = node.first; i < node.first + node.count; ++i) grow(centroids, centroid(bvh.triangles[i]));
    const float parentArea = surfaceArea(node.box);
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
        const float low = centroids.min[axis], high = centroids.max[axis];
        if (!(high > low)) continue;   // every centroid on one plane: nothing to split along this axis
        std::vector<Aabb> binBoxes(settings.bins, emptyBox());
        std::vector<int> binCounts(settings.bins, 0);
        const float scale = static_cast<float>(settings.bins) / (high - low);
        for (int i = node.first; i < node.first + node.count; ++i) {
            const Triangle& triangle = bvh.triangles[i];
            const int bin = std::min(settings.bins - 1, static_cast<int>((centroid(triangle)[axis] - low) * scale));
            ++binCounts[bin];
            grow(binBoxes[bin], boxOf(triangle));
        }
        // Sweep from the left and from the right: plane k lies between bins k and k + 1.
        std::vector<float> leftArea(settings.bins - 1), rightArea(settings.bins - 1);
        std::vector<int> leftCount(settings.bins - 1), rightCount(settings.bins - 1);
        Aabb left = emptyBox(), right = emptyBox();
        int leftSum = 0, rightSum = 0;
        for (int k = 0; k < settings.bins - 1; ++k) {
            grow(left, binBoxes[k]);
            leftSum += binCounts[k];
            leftArea[k] = surfaceArea(left);
            leftCount[k] = leftSum;
            grow(right, binBoxes[settings.bins - 1 - k]);
            rightSum += binCounts[settings.bins - 1 - k];
            rightArea[settings.bins - 2 - k] = surfaceArea(right);
            rightCount[settings.bins - 2 - k] = rightSum;
        }
        for (int k = 0; k < settings.bins - 1; ++k) {
            if (leftCount[k] == 0 || rightCount[k] == 0) continue;
            const float cost = sahSplitCost(leftArea[k], leftCount[k], rightArea[k], rightCount[k], parentArea, settings);
            if (cost < best.cost) best = {axis, low + static_cast<float>(k + 1) / scale, cost};
        }
    }
    return best;
}

void subdivide(Bvh& bvh, int nodeIndex, int depth, const BvhSettings& settings) {
    if (depth >= kMaxBvhDepth) return;   // a leaf, however many triangles it holds
    BvhNode node = bvh.nodes[nodeIndex];
    const Split split = bestSplit(bvh, node, settings);
    const float leafCost = settings.intersectionCost * static_cast<float>(node.count);
    if (split.axis < 0) return;                                             // cannot split: a leaf
    if (node.count <= settings.maxLeafSize && split.cost >= leafCost) return;   // a leaf is cheaper

    // Partition the node's triangles: those left of the plane first.
    auto begin = bvh.triangles.begin() + node.first;
    auto middle = std::partition(begin, begin + node.count, [&](const Triangle& triangle) {
        return centroid(triangle)[split.axis] < split.position;
    });
    const int leftCount = static_cast<int>(middle - begin);
    if (leftCount == 0 || leftCount == node.count) return;   // rounding put every centroid on one side

    const int leftIndex = static_cast<int>(bvh.nodes.size());
    BvhNode leftNode{emptyBox(), node.first, leftCount};
    BvhNode rightNode{emptyBox(), node.first + leftCount, node.count - leftCount};
    for (int i = leftNode.first; i < leftNode.first + leftNode.count; ++i) grow(leftNode.box, boxOf(bvh.triangles[i]));
    for (int i = rightNode.first; i < rightNode.first + rightNode.count; ++i) grow(rightNode.box, boxOf(bvh.triangles[i]));
    bvh.nodes.push_back(leftNode);
    bvh.nodes.push_back(rightNode);
    bvh.nodes[nodeIndex].first = leftIndex;
    bvh.nodes[nodeIndex].count = 0;
    subdivide(bvh, leftIndex, depth + 1, settings);
    subdivide(bvh, leftIndex + 1, depth + 1, settings);
}

// rayHitsBox() (rays.cpp) once more, here, where the compiler can inline it into
// the traversal's inner loop: a call per box test into another file costs a
// tenth of the traversal's time.
inline bool entersBox(const Ray& ray, const Aabb& box, float tMax, float& tEntry) {
    const glm::vec3 t1 = (box.min - ray.origin) * ray.inverseDirection;
    const glm::vec3 t2 = (box.max - ray.origin) * ray.inverseDirection;
    const glm::vec3 nearest = glm::min(t1, t2);
    const glm::vec3 farthest = glm::max(t1, t2);
    const float enter = std::max(std::max(nearest.x, nearest.y), std::max(nearest.z, 0.0f));
    const float leave = std::min(std::min(farthest.x, farthest.y), std::min(farthest.z, tMax));
    tEntry = enter;
    return enter <= leave;
}

} // namespace

float sahSplitCost(float leftArea, int leftCount, float rightArea, int rightCount, float parentArea,
                   const BvhSettings& settings) {
    return settings.traversalCost +
           settings.intersectionCost * (leftArea * static_cast<float>(leftCount) + rightArea * static_cast<float>(rightCount)) /
               parentArea;
}

Bvh buildBvh(std::vector<Triangle> triangles, const BvhSettings& settings) {
    Bvh bvh;
    bvh.triangles = std::move(triangles);
    BvhNode root{emptyBox(), 0, static_cast<int>(bvh.triangles.size())};
    for (const Triangle& triangle : bvh.triangles) grow(root.box, boxOf(triangle));
    bvh.nodes.reserve(2 * bvh.triangles.size());
    bvh.nodes.push_back(root);
    if (!bvh.triangles.empty()) subdivide(bvh, 0, 0, settings);
    return bvh;
}

Hit intersectBvh(const Bvh& bvh, const Ray& ray) {
    Hit hit;
    if (bvh.nodes.empty()) return hit;
    struct Pending {
        int node;
        float entry;   // where the ray enters the node's box
    };
    std::array<Pending, kMaxBvhDepth + 2> stack;   // each level leaves one node behind at most
    int size = 0;
    float entry = 0.0f;
    if (!rayHitsBox(ray, bvh.nodes[0].box, hit.t, entry)) return hit;
    int current = 0;
    while (true) {
        const BvhNode& node = bvh.nodes[current];
        int next = -1;
        if (node.count > 0) {
            for (int i = node.first; i < node.first + node.count; ++i)
                if (rayHitsTriangle(ray, bvh.triangles[i], hit)) hit.triangle = i;
        } else {
            // The children the ray meets before the nearest hit so far: go on with
            // the nearer one at once, and leave the farther one for later.
            float entryLeft = 0.0f, entryRight = 0.0f;
            const bool left = entersBox(ray, bvh.nodes[node.first].box, hit.t, entryLeft);
            const bool right = entersBox(ray, bvh.nodes[node.first + 1].box, hit.t, entryRight);
            if (left && right) {
                const bool leftNearer = entryLeft <= entryRight;
                next = leftNearer ? node.first : node.first + 1;
                stack[size++] = leftNearer ? Pending{node.first + 1, entryRight} : Pending{node.first, entryLeft};
            } else if (left) {
                next = node.first;
            } else if (right) {
                next = node.first + 1;
            }
        }
        // Nothing below this node: the most recent node left for later that the
        // ray enters before the nearest hit found since it was left.
        while (next < 0 && size > 0) {
            const Pending pending = stack[--size];
            if (pending.entry < hit.t) next = pending.node;
        }
        if (next < 0) return hit;
        current = next;
    }
}

} // namespace stoa
