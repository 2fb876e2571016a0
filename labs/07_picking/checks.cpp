// Lab 07's property checks; see checks.hpp. The graded pictures cast every ray
// from the camera at boxes in front of it, where a slab test with the wrong
// entry distance still finds the same nearest triangle; this table asks for the
// entry distance itself.

#include "checks.hpp"
#include "lab07.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace lab07 {

namespace {

// A small triangle whose centroid is at x, with y and z in [0, 1) from a fixed
// sequence: the same triangles every run.
struct TriangleMaker {
    stoa::CheckRandom random{20261129u};
    stoa::Triangle at(float x) {
        const float y = random.next(), z = random.next();
        return {{x - 0.05f, y, z}, {x + 0.05f, y, z}, {x, y + 0.1f, z + 0.05f}};
    }
};

int trianglesUnder(const stoa::Bvh& bvh, int node) {
    const stoa::BvhNode& n = bvh.nodes[static_cast<std::size_t>(node)];
    if (n.count > 0) return n.count;
    return trianglesUnder(bvh, n.first) + trianglesUnder(bvh, n.first + 1);
}

// The root's split as the two children's triangle counts, smaller first; empty
// when the root is a leaf.
std::string rootSplit(const stoa::Bvh& bvh) {
    if (bvh.nodes.empty() || bvh.nodes[0].count > 0) return "no split (the root is a leaf)";
    const int a = trianglesUnder(bvh, bvh.nodes[0].first), b = trianglesUnder(bvh, bvh.nodes[0].first + 1);
    return std::to_string(std::min(a, b)) + " | " + std::to_string(std::max(a, b));
}

// Walks the subtree at `node`: each triangle's leaf, the depth, and whether the
// boxes hold what lies below them. Returns "" or what is wrong.
std::string walkTree(const stoa::Bvh& bvh, int node, int depth, std::vector<int>& leafOf, int& deepest,
                     const stoa::BvhSettings& settings) {
    if (node < 0 || node >= static_cast<int>(bvh.nodes.size()))
        return "a node points to node " + std::to_string(node) + ", past the " + std::to_string(bvh.nodes.size()) + " nodes";
    deepest = std::max(deepest, depth);
    if (depth > stoa::kMaxBvhDepth) return "";   // too deep: the caller says so
    const stoa::BvhNode& n = bvh.nodes[static_cast<std::size_t>(node)];
    if (n.count > 0) {
        glm::vec3 first(0.0f);
        bool sameCentroids = true;
        for (int i = n.first; i < n.first + n.count; ++i) {
            if (i < 0 || i >= static_cast<int>(bvh.triangles.size()))
                return "a leaf holds triangle " + std::to_string(i) + ", past the " + std::to_string(bvh.triangles.size()) + " triangles";
            const stoa::Triangle& t = bvh.triangles[static_cast<std::size_t>(i)];
            for (const glm::vec3& p : {t.p0, t.p1, t.p2})
                if (glm::any(glm::lessThan(p, n.box.min)) || glm::any(glm::greaterThan(p, n.box.max)))
                    return "a leaf's box does not hold its triangle " + std::to_string(i);
            const glm::vec3 c = (t.p0 + t.p1 + t.p2) / 3.0f;
            if (i == n.first) first = c;
            sameCentroids = sameCentroids && glm::length(c - first) < 1e-6f;
            ++leafOf[static_cast<std::size_t>(i)];
        }
        if (n.count > settings.maxLeafSize && depth < stoa::kMaxBvhDepth && !sameCentroids)
            return "a leaf at depth " + std::to_string(depth) + " holds " + std::to_string(n.count) +
                   " triangles, more than maxLeafSize (" + std::to_string(settings.maxLeafSize) +
                   "): a node with more is always split while it can be";
        return "";
    }
    for (int child = n.first; child <= n.first + 1; ++child) {
        if (child < 0 || child >= static_cast<int>(bvh.nodes.size()))
            return "an inner node's child " + std::to_string(child) + " is past the " + std::to_string(bvh.nodes.size()) + " nodes";
        const stoa::Aabb& box = bvh.nodes[static_cast<std::size_t>(child)].box;
        if (glm::any(glm::lessThan(box.min, n.box.min)) || glm::any(glm::greaterThan(box.max, n.box.max)))
            return "an inner node's box at depth " + std::to_string(depth) + " does not hold its child's box";
        const std::string problem = walkTree(bvh, child, depth + 1, leafOf, deepest, settings);
        if (!problem.empty()) return problem;
    }
    return "";
}

// The point of segment ab nearest to p.
glm::vec3 nearestOnSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float t = glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return a + ab * t;
}

// The triangle's point nearest to p by another route than the page's regions:
// p projected on the plane when that lies inside the triangle, else the nearest
// of the three edges' nearest points. `feature` names where it lies.
glm::vec3 nearestByEdges(const glm::vec3& p, const stoa::Triangle& triangle, std::string& feature) {
    const glm::vec3 corners[3] = {triangle.p0, triangle.p1, triangle.p2};
    const glm::vec3 normal = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
    const glm::vec3 onPlane = p - normal * (glm::dot(p - corners[0], normal) / glm::dot(normal, normal));
    bool inside = true;
    for (int i = 0; i < 3; ++i) {
        const glm::vec3& a = corners[i];
        const glm::vec3& b = corners[(i + 1) % 3];
        inside = inside && glm::dot(glm::cross(b - a, onPlane - a), normal) >= 0.0f;
    }
    if (inside) {
        feature = "on the face";
        return onPlane;
    }
    const char* const names[3] = {"p0", "p1", "p2"};
    glm::vec3 best(0.0f);
    float bestDistance = std::numeric_limits<float>::infinity();
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 q = nearestOnSegment(p, corners[i], corners[(i + 1) % 3]);
        if (glm::length(p - q) < bestDistance) {
            bestDistance = glm::length(p - q);
            best = q;
            feature = std::string("on the edge ") + names[i] + names[(i + 1) % 3];
        }
    }
    for (int i = 0; i < 3; ++i)
        if (glm::length(best - corners[i]) < 1e-5f) feature = std::string("at the corner ") + names[i];
    return best;
}

} // namespace

stoa::CheckResult checkBvhCheapestSplit() {
    struct Layout {
        const char* what;
        std::vector<float> xs;   // the centroids' x (or z)
        const char* expected;
        const char* why;
        int axis = 0;            // 2: the triangles along z instead of x; 1: each 10 m across, nearly on top of one another
    };
    TriangleMaker maker;
    // 16 triangles within a metre, one 50 m away: the cheapest plane leaves it alone.
    std::vector<float> outlier;
    for (int i = 0; i < 16; ++i) outlier.push_back(0.06f * static_cast<float>(i));
    outlier.push_back(50.0f);
    // 11 triangles one per bin (12 bins over x = 0 to 12) and 30 in the last bin:
    // the cheapest plane is the last one, between bins 10 and 11.
    std::vector<float> lastPlane;
    for (int i = 0; i < 11; ++i) lastPlane.push_back(0.5f + static_cast<float>(i));
    for (int i = 0; i < 30; ++i) lastPlane.push_back(11.4f + 0.2f * static_cast<float>(i) / 29.0f);
    lastPlane.front() = 0.0f;   // the centroids' box from x = 0
    lastPlane.back() = 12.0f;   // to x = 12: bins one metre wide
    // Five triangles near x = 0, one at x = 4.4 and three near x = 12: the lone one
    // joins the three, whose child then spans 7.7 m, since the other plane gives
    // six triangles a child 4.5 m long (the right-hand count matters as much as the left).
    std::vector<float> loneMiddle = {0.0f, 0.05f, 0.1f, 0.15f, 0.2f, 4.4f, 11.8f, 11.9f, 12.0f};
    // Over 24 m the bins are 2 m wide: one triangle at x = 0, five between 10 and
    // 10.8 and five between 20 and 24. The plane between the two groups is the
    // cheapest; bins of the wrong width put both groups in the last one.
    std::vector<float> twoGroups = {0.0f, 10.0f, 10.2f, 10.4f, 10.6f, 10.8f, 20.0f, 21.0f, 22.0f, 23.0f, 24.0f};
    // The far triangle on the other side, and along z; and four triangles, two
    // and two 100 m apart, few enough for a leaf but cheaper split.
    std::vector<float> outlierBefore;
    for (const float x : outlier) outlierBefore.push_back(x == 50.0f ? -50.0f : x);
    const std::vector<float> twoPairs = {0.0f, 0.1f, 100.0f, 100.1f};
    // Four large triangles nearly on top of one another: each child's box is
    // nearly the parent's, so a split costs more than the leaf.
    const std::vector<float> stacked = {5.0f, 5.01f, 5.02f, 5.03f};
    // The third row mirrored: the lone triangle joins the group on its left.
    const std::vector<float> loneMirrored = {0.0f, 0.1f, 0.2f, 7.6f, 11.8f, 11.85f, 11.9f, 11.95f, 12.0f};
    const Layout layouts[] = {
        {"16 triangles within a metre and one 50 m away along x", outlier, "1 | 16",
         "the cheapest plane leaves the far triangle alone in a child of one"},
        {"11 triangles one a metre from x = 0 to 10.5 and 30 within x = 11.4 to 12", lastPlane, "11 | 30",
         "the cheapest of the bins - 1 planes is the last one, between the last two bins"},
        {"five triangles near x = 0, one at x = 4.4 and three near x = 12", loneMiddle, "4 | 5",
         "the one at x = 4.4 goes with the three: 5 in a small box and 4 over 7.7 m cost less than 6 over 4.5 m and 3 in a small box"},
        {"one triangle at x = 0, five between x = 10 and 10.8 and five between 20 and 24", twoGroups, "5 | 6",
         "over 24 m the 12 bins are 2 m wide, and the plane between the two groups is the cheapest (bin = "
         "(c - low) * bins / (high - low))"},
        {"16 triangles within a metre and one 50 m away along -x", outlierBefore, "1 | 16",
         "the cheapest plane leaves the far triangle alone, on the left as on the right"},
        {"16 triangles within a metre and one 50 m away along z", outlier, "1 | 16",
         "the cheapest plane is along z, the only axis the triangles spread along", 2},
        {"three triangles near x = 0, one at x = 7.6 and five near x = 12", loneMirrored, "4 | 5",
         "the one at x = 7.6 goes with the three on its left: the counts on both sides weigh their boxes' areas"},
        {"four triangles, two at x = 0 and two at x = 100", twoPairs, "2 | 2",
         "a node of at most maxLeafSize triangles is still split when that is cheaper than a leaf (C_leaf = 4 here)"},
        {"four triangles 10 m across, each 1 cm along x from the last", stacked, "no split (the root is a leaf)",
         "a node of at most maxLeafSize triangles whose split costs as much as a leaf or more stays a leaf", 1},
    };
    for (const Layout& layout : layouts) {
        std::vector<stoa::Triangle> triangles;
        for (const float x : layout.xs) {
            stoa::Triangle triangle = maker.at(x);
            if (layout.axis == 2)
                for (glm::vec3* p : {&triangle.p0, &triangle.p1, &triangle.p2}) std::swap(p->x, p->z);
            if (layout.axis == 1) triangle = {{x, 0.0f, 0.0f}, {x + 10.0f, 0.0f, 0.0f}, {x, 10.0f, 0.0f}};
            triangles.push_back(triangle);
        }
        const stoa::Bvh bvh = stoa::buildBvh(triangles);
        const std::string split = rootSplit(bvh);
        if (split != layout.expected)
            return stoa::CheckResult::fail("buildBvh() of " + std::string(layout.what) + " splits the root into " + split +
                                           " triangles; expected " + layout.expected + ": " + layout.why +
                                           " (12 bins, C_t = C_i = 1). Try every plane between two bins on each "
                                           "axis, a child of one triangle included, and keep the cheapest "
                                           "(docs: Where to split)");
    }
    return stoa::CheckResult::pass("buildBvh() splits the root at the cheapest plane: a far triangle alone, the "
                                   "last plane between the bins, a lone triangle joining the group of three, two "
                                   "groups 24 m apart, a far triangle on the left and along z, four triangles in "
                                   "two far pairs split and four stacked ones left a leaf");
}

stoa::CheckResult checkBvhStructure() {
    struct Layout {
        std::string what;
        stoa::BvhSettings settings;
        std::vector<stoa::Triangle> triangles;
    };
    TriangleMaker maker;
    Layout scattered{"300 small triangles scattered through a 10 m cube", {}, {}};
    stoa::CheckRandom random(4242u);
    for (int i = 0; i < 300; ++i) {
        const stoa::Triangle t = maker.at(random.between(0.0f, 10.0f));
        const glm::vec3 shift(0.0f, random.between(0.0f, 9.0f), random.between(0.0f, 9.0f));
        scattered.triangles.push_back({t.p0 + shift, t.p1 + shift, t.p2 + shift});
    }
    // With 2 bins (one plane, in the middle) and leaves of 1, triangles each 2.1
    // times as far out as the one before, their centroids on one line along x,
    // are peeled off one a level: only the depth limit ends the tree. Along +x
    // the rest go down the first children, along -x down the second ones.
    stoa::BvhSettings peel;
    peel.bins = 2;
    peel.maxLeafSize = 1;
    Layout outwards{"110 triangles at x = 2.1^k (2 bins, leaves of 1)", peel, {}};
    Layout backwards{"110 triangles at x = -2.1^k (2 bins, leaves of 1)", peel, {}};
    for (int k = 0; k < 110; ++k) {
        const float x = std::pow(2.1f, static_cast<float>(k));
        outwards.triangles.push_back({{x, 0.0f, 0.0f}, {x, 1.0f, 0.0f}, {x, 0.0f, 1.0f}});
        backwards.triangles.push_back({{-x, 0.0f, 0.0f}, {-x, 1.0f, 0.0f}, {-x, 0.0f, 1.0f}});
    }
    for (const Layout& layout : {scattered, outwards, backwards}) {
        const stoa::Bvh bvh = stoa::buildBvh(layout.triangles, layout.settings);
        const std::string tree = "buildBvh() of " + layout.what + ": ";
        if (bvh.nodes.empty() || bvh.triangles.size() != layout.triangles.size())
            return stoa::CheckResult::fail(tree + "the tree has " + std::to_string(bvh.nodes.size()) + " nodes and " +
                                           std::to_string(bvh.triangles.size()) + " triangles (docs: The BVH)");
        std::vector<int> leafOf(bvh.triangles.size(), 0);
        int deepest = 0;
        const std::string problem = walkTree(bvh, 0, 0, leafOf, deepest, layout.settings);
        if (!problem.empty()) return stoa::CheckResult::fail(tree + problem + " (docs: The BVH)");
        if (deepest > stoa::kMaxBvhDepth)
            return stoa::CheckResult::fail(tree + "the tree grows past depth kMaxBvhDepth (" +
                                           std::to_string(stoa::kMaxBvhDepth) + "), where a node must be a leaf: "
                                           "count the depth "
                                           "down the recursion, the root at 0, both children one deeper "
                                           "(docs: The BVH)");
        for (std::size_t i = 0; i < leafOf.size(); ++i)
            if (leafOf[i] != 1)
                return stoa::CheckResult::fail(tree + "triangle " + std::to_string(i) + " is in " +
                                               std::to_string(leafOf[i]) + " leaves; each must be in exactly one "
                                               "(docs: The BVH)");
    }
    return stoa::CheckResult::pass("buildBvh() makes a sound tree: every triangle in one leaf, boxes that hold "
                                   "their children, small leaves, and no deeper than kMaxBvhDepth");
}

stoa::CheckResult checkClosestPointOnTriangle() {
    // A right triangle, one with an obtuse corner, a sliver, and one tilted in
    // space away from the origin, so that no edge lies along an axis.
    const stoa::Triangle triangles[] = {
        {{0.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f}},
        {{0.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}},
        {{0.0f, 0.0f, 0.0f}, {3.0f, 0.1f, 0.0f}, {1.5f, 0.2f, 0.05f}},
        {{5.0f, 2.0f, -3.0f}, {6.5f, 3.5f, -2.0f}, {4.0f, 4.0f, -4.5f}},
    };
    stoa::CheckRandom random(7007u);
    int tested = 0;
    for (const stoa::Triangle& triangle : triangles) {
        const glm::vec3 low = glm::min(glm::min(triangle.p0, triangle.p1), triangle.p2) - glm::vec3(2.0f);
        const glm::vec3 high = glm::max(glm::max(triangle.p0, triangle.p1), triangle.p2) + glm::vec3(2.0f);
        // Points all around it, so that every corner's, edge's and the face's region has some.
        for (int k = 0; k < 400; ++k, ++tested) {
            const glm::vec3 p(random.between(low.x, high.x), random.between(low.y, high.y),
                              random.between(low.z, high.z));
            std::string feature;
            const glm::vec3 expected = nearestByEdges(p, triangle, feature);
            const glm::vec3 got = stoa::closestPointOnTriangle(p, triangle);
            if (!(glm::length(got - expected) <= 1e-3f))
                return stoa::CheckResult::fail(
                    "closestPointOnTriangle() of the point " + stoa::checkVector(p) + " and the triangle " +
                    stoa::checkVector(triangle.p0) + ", " + stoa::checkVector(triangle.p1) + ", " +
                    stoa::checkVector(triangle.p2) + " gives " + stoa::checkVector(got) + "; the nearest point is " +
                    stoa::checkVector(expected) + ", " + feature + " (distance " +
                    stoa::checkNumber(glm::length(p - expected), 3) + "). Each region has its own answer: a corner, "
                    "the point projected on an edge, a + t (b - a) with t in [0, 1], or the point projected on the "
                    "plane (docs: Closest point on a triangle)");
        }
    }
    return stoa::CheckResult::pass("closestPointOnTriangle() finds the nearest point, on a corner, an edge or the face, "
                                   "for " + std::to_string(tested) + " points around four triangles");
}

stoa::CheckResult checkDeepTreeWalks() {
    // Trees as deep as the builder lets one grow: each inner node has a leaf of
    // one triangle as its first child and the next inner node as its second, down
    // to depth kMaxBvhDepth; the last inner node's second child is a leaf too.
    const int depth = stoa::kMaxBvhDepth;
    auto comb = [&](const std::vector<stoa::Triangle>& triangles) {
        stoa::Bvh bvh;
        bvh.triangles = triangles;
        bvh.nodes.resize(static_cast<std::size_t>(2 * depth + 1));
        for (int d = depth - 1; d >= 0; --d) {   // from the bottom up, so that each box holds what lies below
            const auto inner = static_cast<std::size_t>(2 * d);
            stoa::Aabb leafBox{glm::vec3(std::numeric_limits<float>::infinity()),
                               glm::vec3(-std::numeric_limits<float>::infinity())};
            const stoa::Triangle& t = triangles[static_cast<std::size_t>(d)];
            for (const glm::vec3& p : {t.p0, t.p1, t.p2}) {
                leafBox.min = glm::min(leafBox.min, p);
                leafBox.max = glm::max(leafBox.max, p);
            }
            if (d == depth - 1) {
                const stoa::Triangle& last = triangles[static_cast<std::size_t>(depth)];
                stoa::Aabb lastBox = leafBox;
                lastBox.min = glm::min(glm::min(last.p0, last.p1), last.p2);
                lastBox.max = glm::max(glm::max(last.p0, last.p1), last.p2);
                bvh.nodes[inner + 2] = {lastBox, depth, 1};
            }
            bvh.nodes[inner + 1] = {leafBox, d, 1};
            const stoa::Aabb& below = bvh.nodes[inner + 2].box;
            bvh.nodes[inner] = {{glm::min(leafBox.min, below.min), glm::max(leafBox.max, below.max)}, 2 * d + 1, 0};
        }
        return bvh;
    };
    // Level d's triangle lies across the z axis at z = -100 + d: a ray down -z
    // enters the inner child (whose nearest triangle is the last, at z = -40)
    // before the leaf, so a walk keeps a leaf waiting at every level.
    std::vector<stoa::Triangle> across;
    for (int d = 0; d <= depth; ++d) {
        const float z = -100.0f + static_cast<float>(d);
        across.push_back({{-1.0f, -1.0f, z}, {3.0f, -1.0f, z}, {-1.0f, 3.0f, z}});
    }
    const stoa::Bvh deep = comb(across);
    std::vector<int> found;
    stoa::trianglesNearSphere(deep, {glm::vec3(0.0f, 0.0f, -70.0f), 50.0f}, found);
    std::vector<int> sorted = found;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> all(static_cast<std::size_t>(depth + 1));
    for (int t = 0; t <= depth; ++t) all[static_cast<std::size_t>(t)] = t;
    if (sorted != all)
        return stoa::CheckResult::fail(
            "trianglesNearSphere() on a tree " + std::to_string(depth) + " levels deep (kMaxBvhDepth), whose every "
            "box the sphere overlaps, listed " + std::to_string(found.size()) + " triangles; expected each of its " +
            std::to_string(depth + 1) + " triangles once. Push both children of every inner node whose box "
            "overlaps, and take every triangle of every leaf reached (docs: Finding the triangles)");
    const stoa::Hit hit = stoa::intersectBvh(deep, stoa::makeRay(glm::vec3(0.1f, 0.1f, 100.0f), glm::vec3(0.0f, 0.0f, -1.0f)));
    if (hit.triangle != depth || !(std::fabs(hit.t - 140.0f) <= 1e-3f))
        return stoa::CheckResult::fail(
            "intersectBvh() on a tree " + std::to_string(depth) + " levels deep (kMaxBvhDepth), for a ray down -z "
            "through all of its triangles, gives triangle " + std::to_string(hit.triangle) + " at t = " +
            stoa::checkNumber(hit.t, 3) + "; the nearest is triangle " + std::to_string(depth) + " at t = 140 "
            "(docs: Nearest hit)");
    return stoa::CheckResult::pass("trianglesNearSphere() lists every triangle of a tree " + std::to_string(depth) +
                                   " levels deep, each once, and intersectBvh() finds its nearest hit");
}

stoa::CheckResult checkFixedStepBookkeeping() {
    // A ball dropped from 2 m onto a 20 m floor, advanced by frames of exactly one
    // step, then of uneven lengths: after each one the simulated time is a whole number of steps, and
    // it and the accumulator add up to the frames' time.
    std::vector<stoa::Triangle> floor = {{{-10.0f, 0.0f, -10.0f}, {10.0f, 0.0f, 10.0f}, {10.0f, 0.0f, -10.0f}},
                                         {{-10.0f, 0.0f, -10.0f}, {-10.0f, 0.0f, 10.0f}, {10.0f, 0.0f, 10.0f}}};
    const stoa::Bvh bvh = stoa::buildBvh(floor);
    stoa::Simulation simulation;
    simulation.ball.position = glm::vec3(0.0f, 2.0f, 0.0f);
    const float stepSeconds = simulation.settings.step;
    const float frames[] = {0.0166f, 0.0031f, 0.0502f, 0.0083f, 0.1f, 0.0005f, 0.0211f};
    double framesTime = 0.0;
    for (int i = 0; i < 140; ++i) {
        const float frame = i < 3 ? stepSeconds : frames[i % 7];   // three frames of exactly one step first
        stoa::advanceSimulation(simulation, bvh, frame);
        framesTime += frame;
        const double steps = std::round(simulation.time / stepSeconds);
        const std::string after = "after " + std::to_string(i + 1) + " frames (" + stoa::checkNumber(framesTime, 4) +
                                  " s, steps of " + stoa::checkNumber(stepSeconds, 5) + " s)";
        if (!(simulation.accumulator >= 0.0f && simulation.accumulator < stepSeconds))
            return stoa::CheckResult::fail("advanceSimulation(): " + after + " the accumulator holds " +
                                           stoa::checkNumber(simulation.accumulator, 5) +
                                           " s; it must keep less than one step, 0 included: run steps while it "
                                           "holds a whole one (docs: A fixed time step)");
        if (!(std::fabs(simulation.time - steps * stepSeconds) <= 0.1 * stepSeconds) ||
            !(std::fabs(simulation.time + simulation.accumulator - framesTime) <= 1e-3))
            return stoa::CheckResult::fail("advanceSimulation(): " + after + " simulation.time is " +
                                           stoa::checkNumber(simulation.time, 5) + " s and the accumulator " +
                                           stoa::checkNumber(simulation.accumulator, 5) +
                                           " s; time must count the steps run, a whole number of steps, and the "
                                           "two add up to the frames' time: add each step to simulation.time "
                                           "(docs: A fixed time step)");
    }
    if (simulation.contacts < 1)
        return stoa::CheckResult::fail("advanceSimulation(): a ball dropped from 2 m onto a floor hit it at about "
                                       "6 m/s, faster than settings.sparkSpeed, yet simulation.contacts is " +
                                       std::to_string(simulation.contacts) +
                                       ": count each contact that throws sparks (docs: A fixed time step)");
    return stoa::CheckResult::pass("advanceSimulation() over 140 frames of uneven lengths: the simulated time is a "
                                   "whole number of steps, and it and the accumulator add up to the frames' time");
}

stoa::CheckResult checkSlabTestTable() {
    const float infinity = std::numeric_limits<float>::infinity();
    const stoa::Aabb cube{glm::vec3(-1.0f), glm::vec3(1.0f)};
    const stoa::Aabb away{glm::vec3(2.0f, 1.0f, -6.0f), glm::vec3(4.0f, 3.0f, -5.0f)};
    const glm::vec3 slant = glm::normalize(glm::vec3(1.0f, 0.1f, 0.0f));
    struct Row {
        const char* what;
        glm::vec3 origin, direction;
        stoa::Aabb box;
        float tMax;
        bool hits;
        float entry;
    };
    const Row rows[] = {
        {"along -z at the unit cube", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, true, 4.0f},
        {"the same ray, stopped at t = 3.5 before the cube", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, 3.5f, false, 0.0f},
        {"the same ray, stopped at t = 4.5 inside the cube", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, 4.5f, true, 4.0f},
        {"away from the cube, which is behind it", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 1.0f}, cube, infinity, false, 0.0f},
        {"from inside the cube", {0.2f, 0.3f, 0.0f}, glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)), cube, infinity, true, 0.0f},
        {"slanted, entering through x = -1", {-3.0f, 0.5f, 0.25f}, slant, cube, infinity, true, 2.0f / slant.x},
        {"along -x, entering through x = 1", {5.0f, 0.2f, 0.1f}, {-1.0f, 0.0f, 0.0f}, cube, infinity, true, 4.0f},
        {"parallel to the y slab, inside it", {0.0f, 0.5f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, true, 4.0f},
        {"parallel to the y slab, outside it", {0.0f, 2.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, false, 0.0f},
        {"past a corner of the cube", {3.0f, 3.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, false, 0.0f},
        {"along -z at a box away from the origin", {3.0f, 2.0f, 4.0f}, {0.0f, 0.0f, -1.0f}, away, infinity, true, 9.0f},
        {"along +y at a box away from the origin", {3.5f, -4.0f, -5.5f}, {0.0f, 1.0f, 0.0f}, away, infinity, true, 5.0f},
        {"beside a box away from the origin", {5.0f, 2.0f, 4.0f}, {0.0f, 0.0f, -1.0f}, away, infinity, false, 0.0f},
        {"grazing the cube's edge at (1, 0, 1), where it enters and leaves at once", {2.0f, 0.0f, 0.0f},
         glm::normalize(glm::vec3(-1.0f, 0.0f, 1.0f)), cube, infinity, true, std::sqrt(2.0f)},
    };
    for (const Row& row : rows) {
        const stoa::Ray ray = stoa::makeRay(row.origin, row.direction);
        float entry = -7.0f;   // what tEntry held before the call
        const bool hits = stoa::rayHitsBox(ray, row.box, row.tMax, entry);
        const std::string what = "rayHitsBox() for a ray " + std::string(row.what) + " (origin " +
                                 stoa::checkVector(row.origin) + ", direction " + stoa::checkVector(row.direction) +
                                 ", box " + stoa::checkVector(row.box.min) + " to " + stoa::checkVector(row.box.max) + ")";
        if (hits != row.hits)
            return stoa::CheckResult::fail(what + " says " + (hits ? "hit" : "miss") + "; it " +
                                           (row.hits ? "meets" : "misses") + " the box (docs: The slab test)");
        if (hits && !(std::fabs(entry - row.entry) <= 1e-4f))
            return stoa::CheckResult::fail(what + " set tEntry to " + stoa::checkNumber(entry, 4) + "; the ray enters at t = " +
                                           stoa::checkNumber(row.entry, 4) +
                                           " (t_enter = max(0, the largest of the slabs' entries); set tEntry on a hit) "
                                           "(docs: The slab test)");
    }
    return stoa::CheckResult::pass("rayHitsBox() gives the right hit or miss and entry distance for 14 rays and boxes");
}

stoa::CheckResult checkTriangleHitsOnTheEdges() {
    // The triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), rays straight down -z from
    // z = 1: u and v are the point's x and y, exactly, and t is 1.
    const stoa::Triangle triangle{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    struct Row {
        const char* what;
        glm::vec2 at;
        bool hits;
    };
    const Row rows[] = {
        {"inside", {0.25f, 0.25f}, true},          {"on the edge p0 p2 (u = 0)", {0.0f, 0.5f}, true},
        {"on the edge p0 p1 (v = 0)", {0.5f, 0.0f}, true}, {"on the edge p1 p2 (u + v = 1)", {0.5f, 0.5f}, true},
        {"at the corner p1 (u = 1)", {1.0f, 0.0f}, true},  {"beyond the edge p1 p2", {0.6f, 0.6f}, false},
        {"beside the edge p0 p2", {-0.1f, 0.5f}, false},
    };
    for (const Row& row : rows) {
        stoa::Hit hit;
        const bool hits = stoa::rayHitsTriangle(
            stoa::makeRay(glm::vec3(row.at, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f)), triangle, hit);
        const std::string what = "rayHitsTriangle() for a ray straight down at (" + stoa::checkNumber(row.at.x) + ", " +
                                 stoa::checkNumber(row.at.y) + "), " + row.what +
                                 " of the triangle (0, 0, 0), (1, 0, 0), (0, 1, 0)";
        if (hits != row.hits)
            return stoa::CheckResult::fail(what + (hits ? " reports a hit; it misses" : " reports a miss; it hits") +
                                           ": the triangle holds u >= 0, v >= 0 and u + v <= 1, its edges included "
                                           "(docs: Ray and triangle)");
        if (hits && !(std::fabs(hit.t - 1.0f) <= 1e-5f && std::fabs(hit.u - row.at.x) <= 1e-5f &&
                      std::fabs(hit.v - row.at.y) <= 1e-5f))
            return stoa::CheckResult::fail(what + " sets t = " + stoa::checkNumber(hit.t, 4) + ", u = " +
                                           stoa::checkNumber(hit.u, 4) + ", v = " + stoa::checkNumber(hit.v, 4) +
                                           "; expected t = 1, u = " + stoa::checkNumber(row.at.x) + ", v = " +
                                           stoa::checkNumber(row.at.y) + ": on a hit set hit.t, hit.u and hit.v "
                                           "(docs: Ray and triangle)");
    }
    return stoa::CheckResult::pass("rayHitsTriangle() hits inside, on each edge and at a corner, misses outside, and "
                                   "sets t, u and v");
}

stoa::CheckResult checkRayStartsOnTheNearPlane() {
    // An eye at (1, 2, 3) looking down -z, the near plane 0.5 m in front of it.
    const glm::vec3 eye(1.0f, 2.0f, 3.0f);
    const float near = 0.5f;
    const glm::mat4 view = glm::lookAt(eye, eye + glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 640.0f / 480.0f, near, 100.0f);
    const glm::mat4 inverse = glm::inverse(projection * view);
    const glm::ivec2 viewport(640, 480);
    for (const glm::vec2 pixel : {glm::vec2(320.5f, 240.5f), glm::vec2(100.5f, 80.5f), glm::vec2(600.5f, 400.5f)}) {
        const stoa::Ray ray = stoa::rayThroughPixel(pixel, viewport, inverse);
        const float depth = -(view * glm::vec4(ray.origin, 1.0f)).z;   // in front of the eye
        const std::string what = "rayThroughPixel() for pixel (" + stoa::checkNumber(pixel.x, 1) + ", " +
                                 stoa::checkNumber(pixel.y, 1) + ") of 640 x 480, near plane at 0.5 m, ";
        if (!(std::fabs(depth - near) <= 1e-3f))
            return stoa::CheckResult::fail(
                what + "starts the ray " + stoa::checkNumber(depth, 3) + " m in front of the eye; it starts on the near "
                "plane, the point with z_ndc = -1 taken back through the inverse and divided by w. From nearer it "
                "would pick what lies before the near plane, which is not drawn; from further it would miss what is "
                "drawn there (docs: A ray through a pixel)");
        const glm::vec2 ndc(2.0f * pixel.x / 640.0f - 1.0f, 1.0f - 2.0f * pixel.y / 480.0f);
        const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f), b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
        const glm::vec3 expected = glm::normalize(glm::vec3(b) / b.w - glm::vec3(a) / a.w);
        if (!(glm::length(ray.direction - expected) <= 1e-4f))
            return stoa::CheckResult::fail(what + "gives the direction " + stoa::checkVector(ray.direction, 4) +
                                           "; the ray goes to the pixel's point on the far plane, unit length: " +
                                           stoa::checkVector(expected, 4) + " (docs: A ray through a pixel)");
    }
    return stoa::CheckResult::pass("rayThroughPixel() starts on the near plane and points to the pixel's point on the "
                                   "far plane, for three pixels");
}

} // namespace lab07
