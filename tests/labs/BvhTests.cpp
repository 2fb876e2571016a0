// Lab 07's bounding volume hierarchy against independent references:
//   - sahSplitCost on numbers;
//   - buildBvh's structure (every triangle in exactly one leaf, boxes nested,
//     depth, leaf sizes) on random triangle soups and the Acropolis, and its
//     surface area heuristic cost against a median-split tree built here;
//   - intersectBvh against brute force over every triangle (in double).
// Rays grazing a triangle's edge before the nearest clear hit are left out of the
// exact comparisons by a margin, and counted. RaysTests.cpp tests the ray and
// triangle functions the BVH is built on.

#include "catch.hpp"
#include "PickingReferences.hpp"
#include "TestRandom.hpp"

#include "lab07.hpp"

#include <stoa/geometry/Bounds.hpp>
#include <stoa/geometry/Mesh.hpp>
#include <stoa/scene/AcropolisScene.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using stoa::Aabb;
using stoa::Bvh;
using stoa::BvhNode;
using stoa::BvhSettings;
using stoa::Hit;
using stoa::Ray;
using stoa::Triangle;

namespace {

using stoa::test::picking::conditioning;
using stoa::test::picking::describe;
using stoa::test::picking::kInfinity;
using stoa::test::picking::ReferenceHit;
using stoa::test::picking::referenceIntersect;
using stoa::test::picking::ReferenceTriangle;

using Random = stoa::test::Random;

// --- triangle soups and the Acropolis ------------------------------------------

// `count` triangles: most small, scattered in a 100 m box; a third in a few
// dense clusters; a few long slivers across everything. Each triangle's object
// is its index in the returned list.
std::vector<Triangle> randomSoup(int count, std::uint32_t seed) {
    Random random(seed);
    std::vector<glm::vec3> clusters;
    for (int i = 0; i < 5; ++i) clusters.push_back(random.inBox(glm::vec3(-40.0f), glm::vec3(40.0f)));
    std::vector<Triangle> triangles;
    for (int i = 0; i < count; ++i) {
        glm::vec3 center;
        float size;
        const float kind = random.uniform(0.0f, 1.0f);
        if (kind < 0.6f) {
            center = random.inBox(glm::vec3(-50.0f), glm::vec3(50.0f));
            size = random.uniform(0.3f, 3.0f);
        } else if (kind < 0.97f) {
            const glm::vec3& cluster = clusters[random.below(static_cast<int>(clusters.size()))];
            center = cluster + random.inBox(glm::vec3(-2.0f), glm::vec3(2.0f));
            size = random.uniform(0.05f, 0.6f);
        } else {
            center = random.inBox(glm::vec3(-30.0f), glm::vec3(30.0f));
            size = random.uniform(10.0f, 30.0f);
        }
        Triangle triangle;
        triangle.p0 = center + size * random.inBox(glm::vec3(-1.0f), glm::vec3(1.0f));
        triangle.p1 = center + size * random.inBox(glm::vec3(-1.0f), glm::vec3(1.0f));
        triangle.p2 = center + size * random.inBox(glm::vec3(-1.0f), glm::vec3(1.0f));
        triangle.object = i;
        triangles.push_back(triangle);
    }
    return triangles;
}

// The Acropolis's triangles in world space, as the lab's app collects them (each
// triangle's object is its index here, not the piece's).
const std::vector<Triangle>& acropolisTriangles() {
    static const std::vector<Triangle> triangles = [] {
        std::vector<Triangle> result;
        for (const stoa::AcropolisPiece& piece : stoa::acropolisPieces()) {
            const stoa::Mesh& mesh = *piece.mesh;
            const glm::dmat4 model(piece.model);
            const auto world = [&](std::uint32_t index) {
                return glm::vec3(model * glm::dvec4(glm::dvec3(mesh.vertices[index].position), 1.0));
            };
            for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
                Triangle triangle;
                triangle.p0 = world(mesh.indices[i]);
                triangle.p1 = world(mesh.indices[i + 1]);
                triangle.p2 = world(mesh.indices[i + 2]);
                triangle.object = static_cast<int>(result.size());
                result.push_back(triangle);
            }
        }
        return result;
    }();
    return triangles;
}

struct DBox {
    glm::dvec3 low{kInfinity}, high{-kInfinity};
    void grow(const glm::dvec3& p) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    void grow(const Triangle& t) {
        grow(glm::dvec3(t.p0));
        grow(glm::dvec3(t.p1));
        grow(glm::dvec3(t.p2));
    }
    double area() const {
        const glm::dvec3 s = high - low;
        if (s.x < 0.0 || s.y < 0.0 || s.z < 0.0) return 0.0;
        return 2.0 * (s.x * s.y + s.y * s.z + s.z * s.x);
    }
};

glm::dvec3 centroidOf(const Triangle& t) { return (glm::dvec3(t.p0) + glm::dvec3(t.p1) + glm::dvec3(t.p2)) / 3.0; }

// The SAH cost of a median-split tree: split at the median centroid along the
// longest axis of the centroids' box until at most `maxLeafSize` remain.
// Returns sum(C_t area(inner)) + sum(C_i count area(leaf)), not yet over the root's area.
double medianTreeCost(std::vector<Triangle>& triangles, std::size_t begin, std::size_t end, std::size_t maxLeafSize,
                      const BvhSettings& settings) {
    DBox box, centroids;
    for (std::size_t i = begin; i < end; ++i) {
        box.grow(triangles[i]);
        centroids.grow(centroidOf(triangles[i]));
    }
    const std::size_t count = end - begin;
    if (count <= maxLeafSize) return settings.intersectionCost * static_cast<double>(count) * box.area();
    const glm::dvec3 extent = centroids.high - centroids.low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::size_t middle = begin + count / 2;
    std::nth_element(triangles.begin() + static_cast<std::ptrdiff_t>(begin), triangles.begin() + static_cast<std::ptrdiff_t>(middle),
                     triangles.begin() + static_cast<std::ptrdiff_t>(end),
                     [axis](const Triangle& a, const Triangle& b) { return centroidOf(a)[axis] < centroidOf(b)[axis]; });
    return settings.traversalCost * box.area() + medianTreeCost(triangles, begin, middle, maxLeafSize, settings) +
           medianTreeCost(triangles, middle, end, maxLeafSize, settings);
}

double medianTreeCost(std::vector<Triangle> triangles, const BvhSettings& settings) {
    DBox root;
    for (const Triangle& t : triangles) root.grow(t);
    return medianTreeCost(triangles, 0, triangles.size(), static_cast<std::size_t>(settings.maxLeafSize), settings) /
           root.area();
}

// The student tree's SAH cost, from its own nodes' boxes.
double treeCost(const Bvh& bvh, const BvhSettings& settings) {
    const double rootArea = stoa::surfaceArea(bvh.nodes[0].box);
    double cost = 0.0;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        const BvhNode& node = bvh.nodes[stack.back()];
        stack.pop_back();
        const double area = stoa::surfaceArea(node.box);
        if (node.count > 0) {
            cost += settings.intersectionCost * node.count * area;
        } else {
            cost += settings.traversalCost * area;
            stack.push_back(node.first);
            stack.push_back(node.first + 1);
        }
    }
    return cost / rootArea;
}

bool sameTriangle(const Triangle& a, const Triangle& b) {
    return a.p0 == b.p0 && a.p1 == b.p1 && a.p2 == b.p2 && a.object == b.object;
}

bool boxHolds(const Aabb& outer, const glm::vec3& low, const glm::vec3& high, float slack) {
    for (int axis = 0; axis < 3; ++axis)
        if (low[axis] < outer.min[axis] - slack || high[axis] > outer.max[axis] + slack) return false;
    return true;
}

// Every structural promise of the header, on a tree built from `input` (whose
// objects are their indices). Returns the number of leaves over maxLeafSize.
struct TreeFacts {
    int leaves = 0, inner = 0, depth = 0, oversizedLeaves = 0, largestLeaf = 0;
};

TreeFacts checkStructure(const Bvh& bvh, const std::vector<Triangle>& input, const BvhSettings& settings,
                         bool oversizedOnlyWhenCentroidsCoincide) {
    TreeFacts facts;
    REQUIRE(bvh.triangles.size() == input.size());
    REQUIRE(!bvh.nodes.empty());
    // The same multiset of triangles: each input triangle once (objects are the
    // input's indices), unchanged.
    {
        std::vector<int> seen(input.size(), 0);
        int wrong = 0;
        for (const Triangle& triangle : bvh.triangles) {
            if (triangle.object < 0 || triangle.object >= static_cast<int>(input.size()) ||
                !sameTriangle(triangle, input[static_cast<std::size_t>(triangle.object)])) {
                ++wrong;
                continue;
            }
            ++seen[static_cast<std::size_t>(triangle.object)];
        }
        CHECK(wrong == 0);
        CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<std::ptrdiff_t>(input.size()));
    }
    DBox all;
    for (const Triangle& t : input) all.grow(t);
    const float slack = 1e-6f * static_cast<float>(glm::length(all.high - all.low)) + 1e-6f;

    // Walk the tree: every reachable node once, every triangle index in exactly one leaf.
    std::vector<int> visits(bvh.nodes.size(), 0);
    std::vector<int> covered(bvh.triangles.size(), 0);
    int badNodes = 0, badBoxes = 0, looseLeaves = 0;
    std::string firstProblem;
    struct Pending {
        int node, depth;
    };
    std::vector<Pending> stack{{0, 0}};
    while (!stack.empty()) {
        const Pending pending = stack.back();
        stack.pop_back();
        if (++visits[static_cast<std::size_t>(pending.node)] > 1) {
            ++badNodes;
            if (firstProblem.empty()) firstProblem = "node " + std::to_string(pending.node) + " reached twice";
            continue;
        }
        facts.depth = std::max(facts.depth, pending.depth);
        const BvhNode& node = bvh.nodes[static_cast<std::size_t>(pending.node)];
        if (node.count < 0) {
            ++badNodes;
            if (firstProblem.empty()) firstProblem = "node " + std::to_string(pending.node) + " has a negative count";
            continue;
        }
        if (node.count > 0) {
            ++facts.leaves;
            facts.largestLeaf = std::max(facts.largestLeaf, node.count);
            if (node.first < 0 || node.first + node.count > static_cast<int>(bvh.triangles.size())) {
                ++badNodes;
                if (firstProblem.empty()) firstProblem = "leaf " + std::to_string(pending.node) + " runs past the triangles";
                continue;
            }
            DBox centroids;
            for (int i = node.first; i < node.first + node.count; ++i) {
                ++covered[static_cast<std::size_t>(i)];
                const Triangle& t = bvh.triangles[static_cast<std::size_t>(i)];
                if (!boxHolds(node.box, glm::min(glm::min(t.p0, t.p1), t.p2), glm::max(glm::max(t.p0, t.p1), t.p2), slack)) {
                    ++badBoxes;
                    if (firstProblem.empty())
                        firstProblem = "leaf " + std::to_string(pending.node) + "'s box misses triangle " + std::to_string(i);
                }
                centroids.grow(centroidOf(t));
            }
            if (node.count > settings.maxLeafSize) {
                ++facts.oversizedLeaves;
                // Only a node whose centroids all coincide cannot be split.
                if (oversizedOnlyWhenCentroidsCoincide &&
                    glm::length(centroids.high - centroids.low) > 1e-5 * glm::length(all.high - all.low))
                    ++looseLeaves;
            }
        } else {
            ++facts.inner;
            const int children = node.first;
            if (children <= 0 || children + 1 >= static_cast<int>(bvh.nodes.size())) {
                ++badNodes;
                if (firstProblem.empty())
                    firstProblem = "inner node " + std::to_string(pending.node) + "'s children " + std::to_string(children) +
                                   " are out of range";
                continue;
            }
            for (const int child : {children, children + 1}) {
                const Aabb& box = bvh.nodes[static_cast<std::size_t>(child)].box;
                if (!boxHolds(node.box, box.min, box.max, slack)) {
                    ++badBoxes;
                    if (firstProblem.empty())
                        firstProblem = "node " + std::to_string(pending.node) + "'s box misses its child " + std::to_string(child);
                }
                stack.push_back({child, pending.depth + 1});
            }
        }
        if (node.count == 0 && pending.depth >= stoa::kMaxBvhDepth) {
            ++badNodes;
            if (firstProblem.empty()) firstProblem = "an inner node at depth " + std::to_string(pending.depth);
        }
    }
    INFO(firstProblem);
    CHECK(badNodes == 0);
    CHECK(badBoxes == 0);
    CHECK(std::count(covered.begin(), covered.end(), 1) == static_cast<std::ptrdiff_t>(covered.size()));
    CHECK(facts.depth <= stoa::kMaxBvhDepth);
    CHECK(looseLeaves == 0);
    // The root's box holds every triangle.
    CHECK(boxHolds(bvh.nodes[0].box, glm::vec3(all.low), glm::vec3(all.high), slack));
    return facts;
}

// --- brute force nearest hit ----------------------------------------------------

// The nearest hit over every triangle, in double, with a margin: `sure` is the
// nearest hit inside every triangle by more than the margin, `maybe` the nearest
// within it. The comparison is exact only where they agree.
struct BruteForce {
    double sure = kInfinity, maybe = kInfinity;
    int sureIndex = -1;
    double sureU = 0.0, sureV = 0.0;
    double secondSure = kInfinity;   // the next-nearest hit of another triangle (either kind)
};

BruteForce bruteForce(const std::vector<ReferenceTriangle>& triangles, const Ray& ray) {
    constexpr double kMargin = 1e-5;   // barycentric
    constexpr double kNearest = 1e-3;  // t: hits closer than this are ambiguous (the epsilon of the test)
    const glm::dvec3 origin(ray.origin), direction(ray.direction);
    BruteForce result;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const ReferenceHit hit = referenceIntersect(origin, direction, triangles[i]);
        if (!hit.crosses || hit.t <= 0.0) continue;
        const double margin = hit.margin();
        if (margin < -kMargin) continue;
        const bool clear = margin > kMargin && hit.t > kNearest && hit.cosine > 1e-3;
        if (clear && hit.t < result.sure) {
            result.secondSure = std::min(result.secondSure, result.sure);
            result.sure = hit.t;
            result.sureIndex = static_cast<int>(i);
            result.sureU = hit.u;
            result.sureV = hit.v;
        } else {
            result.secondSure = std::min(result.secondSure, hit.t);
        }
        if (!clear) result.maybe = std::min(result.maybe, hit.t);
    }
    return result;
}

struct RayComparison {
    int compared = 0, hits = 0, misses = 0, skipped = 0, wrongVerdict = 0, wrongT = 0, wrongTriangle = 0, wrongUv = 0;
    std::string firstProblem;
    void problem(const std::string& what) {
        if (firstProblem.empty()) firstProblem = what;
    }
};

// intersectBvh(bvh, ray) for every ray against brute force over `input`.
RayComparison compareWithBruteForce(const Bvh& bvh, const std::vector<Triangle>& input, const std::vector<Ray>& rays) {
    std::vector<ReferenceTriangle> references;
    references.reserve(input.size());
    for (const Triangle& t : input) references.emplace_back(t);
    RayComparison result;
    for (const Ray& ray : rays) {
        const BruteForce expected = bruteForce(references, ray);
        const Hit hit = stoa::intersectBvh(bvh, ray);
        // Ambiguous: a triangle grazed at its edge (or too close) before the nearest clear hit.
        if (expected.maybe < kInfinity && expected.maybe <= expected.sure * (1.0 + 1e-4)) {
            ++result.skipped;
            continue;
        }
        ++result.compared;
        if (expected.sureIndex < 0) {
            ++result.misses;
            if (hit.found()) {
                ++result.wrongVerdict;
                result.problem("a hit at t " + std::to_string(hit.t) + " where none is: " + describe(ray));
            }
            continue;
        }
        ++result.hits;
        if (!hit.found() || hit.triangle >= static_cast<int>(bvh.triangles.size())) {
            ++result.wrongVerdict;
            result.problem("no hit where triangle " + std::to_string(expected.sureIndex) + " is at t " +
                           std::to_string(expected.sure) + ": " + describe(ray));
            continue;
        }
        if (std::abs(static_cast<double>(hit.t) - expected.sure) > 1e-4 * std::max(1.0, expected.sure)) {
            ++result.wrongT;
            result.problem("t " + std::to_string(hit.t) + " where the nearest is " + std::to_string(expected.sure) + ": " +
                           describe(ray));
            continue;
        }
        // The triangle, where no other is as near.
        if (expected.secondSure > expected.sure * (1.0 + 1e-4) + 1e-6) {
            const int object = bvh.triangles[static_cast<std::size_t>(hit.triangle)].object;
            // u, v as rayHitsTriangle's test wants them: within 1e-4 where well-conditioned.
            const double condition = conditioning(glm::dvec3(ray.origin), glm::dvec3(ray.direction),
                                                  references[static_cast<std::size_t>(expected.sureIndex)]);
            const double uvTolerance = std::max(1e-4, 5e-7 * condition);
            if (object != expected.sureIndex) {
                ++result.wrongTriangle;
                result.problem("triangle " + std::to_string(object) + " where " + std::to_string(expected.sureIndex) +
                               " is nearest: " + describe(ray));
            } else if (std::abs(hit.u - expected.sureU) > uvTolerance || std::abs(hit.v - expected.sureV) > uvTolerance) {
                ++result.wrongUv;
                result.problem("u, v " + std::to_string(hit.u) + ", " + std::to_string(hit.v) + " where they are " +
                               std::to_string(expected.sureU) + ", " + std::to_string(expected.sureV));
            }
        }
    }
    return result;
}

// Rays at a set of triangles: from outside their box towards a point inside a
// random triangle (mostly hits), from inside in random directions, and towards
// random points of the box.
std::vector<Ray> raysInto(const std::vector<Triangle>& triangles, int count, std::uint32_t seed) {
    Random random(seed);
    DBox box;
    for (const Triangle& t : triangles) box.grow(t);
    const glm::vec3 low(box.low), high(box.high);
    const glm::vec3 center = 0.5f * (low + high);
    const float radius = 0.5f * glm::length(high - low);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        glm::vec3 origin, direction;
        const int kind = i % 4;
        if (kind <= 1) {
            origin = center + random.uniform(1.05f, 1.6f) * radius * random.unitVector();
            const Triangle& t = triangles[static_cast<std::size_t>(random.below(static_cast<int>(triangles.size())))];
            float a = random.uniform(0.0f, 1.0f), b = random.uniform(0.0f, 1.0f);
            if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
            direction = glm::normalize((1.0f - a - b) * t.p0 + a * t.p1 + b * t.p2 - origin);
        } else if (kind == 2) {
            origin = random.inBox(low, high);
            direction = random.unitVector();
        } else {
            origin = center + random.uniform(0.5f, 1.5f) * radius * random.unitVector();
            direction = glm::normalize(random.inBox(low, high) - origin);
        }
        if (i % 10 == 9) direction *= random.uniform(0.2f, 5.0f);   // t in other units
        rays.push_back(stoa::makeRay(origin, direction));
    }
    return rays;
}

void requireRaysAgree(const RayComparison& result, int rays) {
    INFO(result.firstProblem);
    INFO(result.compared << " rays compared (" << result.hits << " hits, " << result.misses << " misses), "
                         << result.skipped << " left out as grazing an edge");
    CHECK(result.wrongVerdict == 0);
    CHECK(result.wrongT == 0);
    CHECK(result.wrongTriangle == 0);
    CHECK(result.wrongUv == 0);
    CHECK(result.skipped <= rays / 50);
    CHECK(result.hits >= rays / 4);
}

} // namespace

// --- bvh.cpp: sahSplitCost ----------------------------------------------------

TEST_CASE("Lab 07: sahSplitCost is C_t plus C_i times the children's area-weighted counts over the parent's area",
          "[lab07][picking]") {
    const BvhSettings defaults;
    CHECK(stoa::sahSplitCost(3.0f, 4, 5.0f, 6, 10.0f, defaults) == Approx(1.0 + (12.0 + 30.0) / 10.0));
    CHECK(stoa::sahSplitCost(3.0f, 4, 5.0f, 6, 40.0f, defaults) == Approx(1.0 + (12.0 + 30.0) / 40.0));
    BvhSettings costly;
    costly.traversalCost = 1.5f;
    costly.intersectionCost = 2.0f;
    CHECK(stoa::sahSplitCost(3.0f, 4, 5.0f, 6, 10.0f, costly) == Approx(1.5 + 2.0 * (12.0 + 30.0) / 10.0));
    CHECK(stoa::sahSplitCost(0.5f, 7, 2.25f, 1, 4.0f, costly) == Approx(1.5 + 2.0 * (3.5 + 2.25) / 4.0));
    // Children as big as the parent, one triangle each: C_t + 2 C_i.
    CHECK(stoa::sahSplitCost(8.0f, 1, 8.0f, 1, 8.0f, defaults) == Approx(3.0));
    // Halving every area leaves the cost as it was: only the ratios count.
    CHECK(stoa::sahSplitCost(1.5f, 4, 2.5f, 6, 5.0f, costly) == Approx(stoa::sahSplitCost(3.0f, 4, 5.0f, 6, 10.0f, costly)));
    // An empty child costs nothing but the traversal.
    CHECK(stoa::sahSplitCost(0.0f, 0, 6.0f, 3, 12.0f, defaults) == Approx(1.0 + 18.0 / 12.0));
}

// --- bvh.cpp: buildBvh --------------------------------------------------------

TEST_CASE("Lab 07: buildBvh on random triangle soups keeps every triangle once in nested boxes", "[lab07][picking]") {
    for (const int count : {1, 2, 5, 100, 1000, 20000}) {
        INFO(count << " triangles");
        const std::vector<Triangle> soup = randomSoup(count, 700u + static_cast<std::uint32_t>(count));
        const BvhSettings settings;
        const Bvh bvh = stoa::buildBvh(soup, settings);
        const TreeFacts facts = checkStructure(bvh, soup, settings, true);
        CHECK(facts.oversizedLeaves == 0);
        if (count > settings.maxLeafSize) CHECK(facts.inner > 0);
        CHECK(facts.leaves == facts.inner + 1);
    }
    // Other settings: smaller leaves, fewer bins.
    BvhSettings small;
    small.maxLeafSize = 1;
    small.bins = 4;
    const std::vector<Triangle> soup = randomSoup(3000, 7007u);
    const Bvh bvh = stoa::buildBvh(soup, small);
    const TreeFacts facts = checkStructure(bvh, soup, small, true);
    CHECK(facts.oversizedLeaves == 0);
    CHECK(facts.largestLeaf == 1);
}

TEST_CASE("Lab 07: buildBvh on the Acropolis keeps every triangle once in nested boxes", "[lab07][picking]") {
    const std::vector<Triangle>& triangles = acropolisTriangles();
    REQUIRE(triangles.size() > 10000);
    const BvhSettings settings;
    const Bvh bvh = stoa::buildBvh(triangles, settings);
    const TreeFacts facts = checkStructure(bvh, triangles, settings, true);
    INFO(facts.leaves << " leaves, depth " << facts.depth << ", " << facts.oversizedLeaves << " over "
                      << settings.maxLeafSize << " triangles, the largest " << facts.largestLeaf);
    CHECK(facts.leaves > static_cast<int>(triangles.size()) / 8);
}

TEST_CASE("Lab 07: buildBvh's tree costs less by the surface area heuristic than a median split",
          "[lab07][picking]") {
    const BvhSettings settings;
    const std::vector<std::pair<std::string, std::vector<Triangle>>> sets = {
        {"20000 random triangles", randomSoup(20000, 720u)},
        {"the Acropolis", acropolisTriangles()},
    };
    for (const auto& [name, triangles] : sets) {
        INFO(name);
        const Bvh bvh = stoa::buildBvh(triangles, settings);
        const double ours = treeCost(bvh, settings);
        const double median = medianTreeCost(triangles, settings);
        INFO("SAH cost " << ours << ", median split " << median);
        CHECK(ours < median);
        // And not absurdly: at least a leaf's worth of work and below testing every triangle.
        CHECK(ours > settings.intersectionCost);
        CHECK(ours < 0.01 * static_cast<double>(triangles.size()));
    }
}

// --- bvh.cpp: intersectBvh ----------------------------------------------------

TEST_CASE("Lab 07: intersectBvh finds the nearest hit as brute force does, in random triangle soups",
          "[lab07][picking]") {
    for (const int count : {1, 5, 100, 1000, 20000}) {
        INFO(count << " triangles");
        const std::vector<Triangle> soup = randomSoup(count, 800u + static_cast<std::uint32_t>(count));
        const Bvh bvh = stoa::buildBvh(soup);
        const int rayCount = count >= 20000 ? 1000 : 3000;
        const std::vector<Ray> rays = raysInto(soup, rayCount, 81u + static_cast<std::uint32_t>(count));
        requireRaysAgree(compareWithBruteForce(bvh, soup, rays), rayCount);
    }
}

TEST_CASE("Lab 07: intersectBvh finds the nearest hit as brute force does, in the Acropolis", "[lab07][picking]") {
    const std::vector<Triangle>& triangles = acropolisTriangles();
    const Bvh bvh = stoa::buildBvh(triangles);
    std::vector<Ray> rays = raysInto(triangles, 800, 90u);
    // And from where a visitor stands, at eye height, in every direction.
    Random random(91);
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 eye(random.uniform(-14.0f, 14.0f), random.uniform(1.0f, 9.0f), random.uniform(-14.0f, 14.0f));
        rays.push_back(stoa::makeRay(eye, random.unitVector()));
    }
    requireRaysAgree(compareWithBruteForce(bvh, triangles, rays), static_cast<int>(rays.size()));
}

TEST_CASE("Lab 07: intersectBvh and a hand-made scene of stacked squares", "[lab07][picking]") {
    // Ten unit squares (two triangles each) one behind the other along -z: the
    // ray from the front hits the first, from the back the last, between them the next.
    std::vector<Triangle> triangles;
    for (int i = 0; i < 10; ++i) {
        const float z = -static_cast<float>(i);
        triangles.push_back({{-1, -1, z}, {1, -1, z}, {1, 1, z}, 2 * i});
        triangles.push_back({{-1, -1, z}, {1, 1, z}, {-1, 1, z}, 2 * i + 1});
    }
    const Bvh bvh = stoa::buildBvh(triangles);
    const auto objectHit = [&](const Ray& ray, float& t) {
        const Hit hit = stoa::intersectBvh(bvh, ray);
        t = hit.t;
        return hit.found() ? bvh.triangles[static_cast<std::size_t>(hit.triangle)].object : -1;
    };
    float t = 0.0f;
    CHECK(objectHit(stoa::makeRay({0.3f, -0.4f, 5.0f}, {0, 0, -1}), t) == 0);
    CHECK(t == Approx(5.0f));
    CHECK(objectHit(stoa::makeRay({0.3f, -0.4f, -20.0f}, {0, 0, 1}), t) == 18);
    CHECK(t == Approx(11.0f));
    CHECK(objectHit(stoa::makeRay({-0.3f, 0.4f, -4.5f}, {0, 0, -1}), t) == 11);
    CHECK(t == Approx(0.5f));
    CHECK(objectHit(stoa::makeRay({-0.3f, 0.4f, -4.5f}, {0, 0, 1}), t) == 9);
    CHECK(objectHit(stoa::makeRay({3.0f, 0.0f, 5.0f}, {0, 0, -1}), t) == -1);
    CHECK(objectHit(stoa::makeRay({0.0f, 0.0f, 5.0f}, {0, 0, 1}), t) == -1);
}
