// Lab 07's rays, slab and triangle tests, and BVH against independent references:
//   - rayThroughPixel against glm::perspective * glm::lookAt: the ray starts on the
//     near plane, has unit direction, and a point along it projects back onto the
//     pixel it was cast through (y down); the centre pixel looks forward;
//   - rayHitsBox against the ray's intersections with the box's six face
//     rectangles (in double), for thousands of random rays and boxes, axis-parallel
//     rays (infinite inverse direction components) and origins inside among them;
//   - rayHitsTriangle against the ray's intersection with the triangle's plane and
//     barycentric coordinates from signed areas (in double);
//   - buildBvh's structure (every triangle in exactly one leaf, boxes nested,
//     depth, leaf sizes) on random triangle soups and the Acropolis, and its
//     surface area heuristic cost against a median-split tree built here;
//   - intersectBvh against brute force over every triangle;
//   - sahSplitCost on numbers.
// Cases near a boundary (a ray grazing an edge or a box's face, a hit at tMax) are
// left out of the exact comparisons by a margin, and counted.

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab07.hpp"

#include <stoa/geometry/Bounds.hpp>
#include <stoa/geometry/Mesh.hpp>
#include <stoa/scene/AcropolisScene.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using stoa::Aabb;
using stoa::Bvh;
using stoa::BvhNode;
using stoa::BvhSettings;
using stoa::Hit;
using stoa::Ray;
using stoa::Triangle;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using Random = stoa::test::Random;

std::string describe(const glm::vec3& v) {
    std::ostringstream out;
    out.precision(9);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

std::string describe(const Ray& ray) { return "origin " + describe(ray.origin) + " direction " + describe(ray.direction); }

// --- cameras ------------------------------------------------------------------

struct TestCamera {
    std::string name;
    glm::vec3 eye, target;
    float fovYDegrees, near, far;
    glm::ivec2 viewport;
    glm::mat4 view() const { return glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f)); }
    glm::mat4 projection() const {
        return glm::perspective(glm::radians(fovYDegrees), static_cast<float>(viewport.x) / static_cast<float>(viewport.y),
                                near, far);
    }
};

std::vector<TestCamera> testCameras() {
    return {
        {"60 deg, 1280x720, near 0.1 far 100", {0, 2, 5}, {0, 1, 0}, 60.0f, 0.1f, 100.0f, {1280, 720}},
        {"35 deg, 512x512, near 1 far 500, off the origin", {30, 10, -20}, {0, 0, 0}, 35.0f, 1.0f, 500.0f, {512, 512}},
        {"90 deg, 300x600, looking almost straight down", {1, 40, 2}, {0, 0, 0}, 90.0f, 0.5f, 60.0f, {300, 600}},
        {"25 deg, 1920x800, looking up and back", {-4, 1, 9}, {-10, 12, 30}, 25.0f, 0.3f, 80.0f, {1920, 800}},
        {"70 deg, 640x480, the lab's view of the Acropolis", {0, 4, 22}, {0, 2, -2}, 70.0f, 0.1f, 200.0f, {640, 480}},
    };
}

// --- the reference box test: the six face rectangles, in double ----------------

// Where the ray first meets the box `low`..`high` at t >= 0: 0 when the origin
// is inside, else the nearest t at which it crosses one of the six face
// rectangles; infinity when it never does.
double referenceBoxEntry(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& low,
                         const glm::dvec3& high) {
    bool inside = true;
    for (int axis = 0; axis < 3; ++axis) inside = inside && origin[axis] >= low[axis] && origin[axis] <= high[axis];
    if (inside) return 0.0;
    double best = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0.0) continue;   // parallel to both faces of this axis
        for (const double plane : {low[axis], high[axis]}) {
            const double t = (plane - origin[axis]) / direction[axis];
            if (t < 0.0 || t >= best) continue;
            const glm::dvec3 point = origin + t * direction;
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            if (point[a] >= low[a] && point[a] <= high[a] && point[b] >= low[b] && point[b] <= high[b]) best = t;
        }
    }
    return best;
}

// --- the reference triangle test: the plane, then signed areas, in double -------

struct ReferenceTriangle {
    glm::dvec3 p0, e1, e2, normal;   // normal = e1 x e2
    double normalLength2 = 0.0;
    explicit ReferenceTriangle(const Triangle& triangle)
        : p0(triangle.p0), e1(glm::dvec3(triangle.p1) - p0), e2(glm::dvec3(triangle.p2) - p0),
          normal(glm::cross(e1, e2)), normalLength2(glm::dot(normal, normal)) {}
};

struct ReferenceHit {
    bool crosses = false;   // the ray's line is not parallel to the plane
    double t = 0.0, u = 0.0, v = 0.0;
    double cosine = 0.0;    // |cos| of the angle between the ray and the normal
    double margin() const { return std::min({u, v, 1.0 - u - v}); }   // > 0 inside, < 0 outside
};

ReferenceHit referenceIntersect(const glm::dvec3& origin, const glm::dvec3& direction, const ReferenceTriangle& triangle) {
    ReferenceHit hit;
    const double denominator = glm::dot(triangle.normal, direction);
    const double scale = std::sqrt(triangle.normalLength2) * glm::length(direction);
    if (scale == 0.0 || std::abs(denominator) <= 1e-12 * scale) return hit;
    hit.crosses = true;
    hit.cosine = std::abs(denominator) / scale;
    hit.t = glm::dot(triangle.normal, triangle.p0 - origin) / denominator;
    const glm::dvec3 w = origin + hit.t * direction - triangle.p0;
    // Areas of the sub-triangles opposite p1 and p2, signed by the normal, over the whole.
    hit.u = glm::dot(glm::cross(w, triangle.e2), triangle.normal) / triangle.normalLength2;
    hit.v = glm::dot(glm::cross(triangle.e1, w), triangle.normal) / triangle.normalLength2;
    return hit;
}

// How many times float's rounding error u, v may carry for this ray and
// triangle: the origin's distance from p0 against the triangle's size, over the
// sine of its corner and the cosine of the ray with its normal (Moller-Trumbore's
// determinant). Thin triangles seen edge-on from afar are ill-conditioned.
double conditioning(const glm::dvec3& origin, const glm::dvec3& direction, const ReferenceTriangle& triangle) {
    const double e1 = glm::length(triangle.e1), e2 = glm::length(triangle.e2);
    const double determinant = std::abs(glm::dot(triangle.normal, direction));
    if (determinant == 0.0) return kInfinity;
    return glm::length(origin - triangle.p0) * glm::length(direction) * std::max(e1, e2) / determinant;
}

ReferenceHit referenceIntersect(const Ray& ray, const Triangle& triangle) {
    return referenceIntersect(glm::dvec3(ray.origin), glm::dvec3(ray.direction), ReferenceTriangle(triangle));
}

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

// --- rays.cpp: rayThroughPixel ------------------------------------------------

TEST_CASE("Lab 07: rayThroughPixel starts on the near plane and projects back onto its pixel", "[lab07][picking]") {
    Random random(7);
    for (const TestCamera& camera : testCameras()) {
        INFO(camera.name);
        const glm::mat4 view = camera.view(), projection = camera.projection();
        const glm::mat4 inverseViewProjection = glm::inverse(projection * view);
        const glm::dmat4 viewProjection = glm::dmat4(projection) * glm::dmat4(view);
        const glm::dmat4 viewD(view);
        const glm::dvec2 size(camera.viewport);
        std::vector<glm::vec2> pixels = {{0.5f, 0.5f},
                                         {size.x - 0.5f, 0.5f},
                                         {0.5f, size.y - 0.5f},
                                         {size.x - 0.5f, size.y - 0.5f},
                                         {size.x / 2.0f, size.y / 2.0f},
                                         {0.0f, 0.0f},
                                         {static_cast<float>(size.x), static_cast<float>(size.y)}};
        for (int i = 0; i < 200; ++i)
            pixels.push_back({std::floor(random.uniform(0.0f, static_cast<float>(size.x))) + 0.5f,
                              std::floor(random.uniform(0.0f, static_cast<float>(size.y))) + 0.5f});
        for (int i = 0; i < 50; ++i)   // anywhere, not only at centres
            pixels.push_back({random.uniform(0.0f, static_cast<float>(size.x)), random.uniform(0.0f, static_cast<float>(size.y))});
        double worstPixel = 0.0, worstLength = 0.0, worstNear = 0.0;
        int wrongInverse = 0;
        glm::vec2 worstAt(0.0f);
        for (const glm::vec2& pixel : pixels) {
            const Ray ray = stoa::rayThroughPixel(pixel, camera.viewport, inverseViewProjection);
            worstLength = std::max(worstLength, std::abs(glm::length(glm::dvec3(ray.direction)) - 1.0));
            // On the near plane: its depth in front of the camera is `near`.
            const double depth = -(viewD * glm::dvec4(glm::dvec3(ray.origin), 1.0)).z;
            worstNear = std::max(worstNear, std::abs(depth - camera.near) / camera.near);
            // A point along it projects onto the pixel (y down from the top).
            const glm::dvec4 clip = viewProjection * glm::dvec4(glm::dvec3(ray.origin) + 5.0 * glm::dvec3(ray.direction), 1.0);
            const glm::dvec2 ndc(clip.x / clip.w, clip.y / clip.w);
            const glm::dvec2 back((ndc.x + 1.0) / 2.0 * size.x, (1.0 - ndc.y) / 2.0 * size.y);
            const double error = glm::length(back - glm::dvec2(pixel));
            if (!(error <= worstPixel)) worstPixel = error, worstAt = pixel;
            // inverseDirection goes with the direction (makeRay).
            for (int axis = 0; axis < 3; ++axis) {
                const float product = ray.inverseDirection[axis] * ray.direction[axis];
                if (ray.direction[axis] != 0.0f ? std::abs(product - 1.0f) > 1e-6f : !std::isinf(ray.inverseDirection[axis]))
                    ++wrongInverse;
            }
        }
        INFO("worst pixel " << worstAt.x << ", " << worstAt.y);
        CHECK(wrongInverse == 0);
        // Float's rounding through the inverse matrix: up to 0.0075 px for the solution.
        CHECK(worstPixel < 0.02);
        CHECK(worstLength < 1e-5);
        CHECK(worstNear < 1e-3);
    }
}

TEST_CASE("Lab 07: rayThroughPixel through the centre looks forward, through the top-left corner up and left",
          "[lab07][picking]") {
    for (const TestCamera& camera : testCameras()) {
        INFO(camera.name);
        const glm::mat4 view = camera.view();
        const glm::mat4 inverseViewProjection = glm::inverse(camera.projection() * view);
        const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
        const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
        const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
        const Ray centre = stoa::rayThroughPixel(glm::vec2(camera.viewport) / 2.0f, camera.viewport, inverseViewProjection);
        CHECK(glm::length(centre.direction - forward) < 1e-4f);
        // It starts near + eye along the forward direction.
        CHECK(glm::length(centre.origin - (camera.eye + camera.near * forward)) < 1e-4f * (1.0f + glm::length(camera.eye)));
        // Pixel rows run down: the top-left pixel is above and left of the centre.
        const Ray topLeft = stoa::rayThroughPixel({0.5f, 0.5f}, camera.viewport, inverseViewProjection);
        CHECK(glm::dot(topLeft.direction, up) > 0.05f);
        CHECK(glm::dot(topLeft.direction, right) < -0.05f);
        const Ray bottomRight = stoa::rayThroughPixel(glm::vec2(camera.viewport) - 0.5f, camera.viewport, inverseViewProjection);
        CHECK(glm::dot(bottomRight.direction, up) < -0.05f);
        CHECK(glm::dot(bottomRight.direction, right) > 0.05f);
        // Half the vertical field of view between the centre and the top edge's middle.
        const Ray top = stoa::rayThroughPixel({camera.viewport.x / 2.0f, 0.0f}, camera.viewport, inverseViewProjection);
        const float angle = std::acos(std::clamp(glm::dot(top.direction, forward), -1.0f, 1.0f));
        CHECK(glm::degrees(angle) == Approx(camera.fovYDegrees / 2.0f).epsilon(1e-3));
    }
}

// --- rays.cpp: rayHitsBox -----------------------------------------------------

TEST_CASE("Lab 07: rayHitsBox agrees with the box's face rectangles for thousands of random rays", "[lab07][picking]") {
    Random random(70);
    int compared = 0, hits = 0, misses = 0, inside = 0, axisParallel = 0, axisParallelHits = 0, cutOff = 0, away = 0,
        skipped = 0;
    int wrongVerdict = 0, wrongEntry = 0;
    std::string firstProblem;
    for (int trial = 0; trial < 20000; ++trial) {
        const glm::vec3 center = random.inBox(glm::vec3(-10.0f), glm::vec3(10.0f));
        const glm::vec3 half = random.inBox(glm::vec3(0.1f), glm::vec3(5.0f));
        const Aabb box{center - half, center + half};
        glm::vec3 origin, direction;
        const int kind = trial % 10;
        if (kind == 0) {
            // Inside the box.
            origin = random.inBox(box.min, box.max);
            direction = random.unitVector();
        } else if (kind <= 2) {
            // Along an axis, from outside, the other two coordinates in (or near) the box.
            const int axis = random.below(3);
            origin = random.inBox(box.min - 0.3f * half, box.max + 0.3f * half);
            const float side = random.chance(0.5f) ? 1.0f : -1.0f;
            origin[axis] = center[axis] + side * (half[axis] + random.uniform(0.5f, 10.0f));
            direction = glm::vec3(0.0f);
            direction[axis] = random.chance(0.8f) ? -side : side;   // mostly towards the box
        } else if (kind <= 6) {
            // Towards (near) the box, from anywhere; sometimes in a coordinate plane.
            origin = random.inBox(glm::vec3(-25.0f), glm::vec3(25.0f));
            direction = glm::normalize(random.inBox(box.min - 0.2f * half, box.max + 0.2f * half) - origin);
            if (kind == 6) {
                const int axis = random.below(3);
                direction[axis] = 0.0f;
                if (glm::length(direction) < 1e-3f) direction[(axis + 1) % 3] = 1.0f;
            }
        } else {
            origin = random.inBox(glm::vec3(-25.0f), glm::vec3(25.0f));
            direction = random.unitVector();
        }
        if (trial % 7 == 3) direction *= random.uniform(0.2f, 5.0f);
        const float tMax = random.chance(0.4f) ? std::numeric_limits<float>::infinity() : random.uniform(0.0f, 60.0f);
        const Ray ray = stoa::makeRay(origin, direction);

        // The reference, on the box grown and shrunk by a margin: only where both agree.
        const glm::dvec3 o(origin), d(direction), low(box.min), high(box.max);
        const double margin = 1e-4 * (1.0 + glm::length(glm::dvec3(half)));
        const double exact = referenceBoxEntry(o, d, low, high);
        const double outer = referenceBoxEntry(o, d, low - margin, high + margin);
        const double inner = referenceBoxEntry(o, d, low + margin, high - margin);
        const double tolerance = 1e-4 * std::max(1.0, std::isinf(exact) ? 1.0 : exact) / std::max(1e-3, glm::length(d));
        const bool surelyHits = inner < kInfinity && inner <= static_cast<double>(tMax) - tolerance;
        const bool surelyMisses = !(outer < kInfinity && outer <= static_cast<double>(tMax) + tolerance);
        if (!surelyHits && !surelyMisses) {
            ++skipped;
            continue;
        }
        ++compared;
        if ((direction.x == 0.0f) + (direction.y == 0.0f) + (direction.z == 0.0f) == 2) {
            ++axisParallel;
            if (surelyHits) ++axisParallelHits;
        }
        if (exact == 0.0) ++inside;
        if (exact < kInfinity && exact > static_cast<double>(tMax)) ++cutOff;
        if (exact == kInfinity && glm::dot(glm::dvec3(box.center()) - o, d) < 0.0) ++away;
        float entry = -1.0f;
        const bool hit = stoa::rayHitsBox(ray, box, tMax, entry);
        if (hit != surelyHits) {
            ++wrongVerdict;
            if (firstProblem.empty())
                firstProblem = std::string(hit ? "a hit" : "a miss") + " where the faces say otherwise: box " + describe(box.min) +
                               " .. " + describe(box.max) + ", " + describe(ray) + ", tMax " + std::to_string(tMax) +
                               ", entry " + std::to_string(exact);
            continue;
        }
        if (hit) {
            ++hits;
            // Between where it enters the grown and the shrunk box; 0 from inside.
            const bool inShrunk = inner == 0.0;
            const bool ok = inShrunk ? entry == 0.0f
                                     : static_cast<double>(entry) >= outer - tolerance && static_cast<double>(entry) <= inner + tolerance;
            if (!ok) {
                ++wrongEntry;
                if (firstProblem.empty())
                    firstProblem = "tEntry " + std::to_string(entry) + " where the ray enters at " + std::to_string(exact) +
                                   ": box " + describe(box.min) + " .. " + describe(box.max) + ", " + describe(ray);
            }
        } else {
            ++misses;
        }
    }
    INFO(firstProblem);
    INFO(compared << " compared (" << hits << " hits, " << misses << " misses, " << inside << " from inside, "
                  << axisParallel << " axis-parallel of which " << axisParallelHits << " hits, " << cutOff
                  << " cut off by tMax, " << away << " pointing away), " << skipped << " left out at a margin");
    CHECK(wrongVerdict == 0);
    CHECK(wrongEntry == 0);
    CHECK(skipped < 200);
    CHECK(hits > 4000);
    CHECK(misses > 4000);
    CHECK(inside > 1000);
    CHECK(axisParallelHits > 1000);
    CHECK(cutOff > 500);
    CHECK(away > 500);
}

TEST_CASE("Lab 07: rayHitsBox on the cases by hand", "[lab07][picking]") {
    const Aabb box{{-1.0f, -2.0f, -3.0f}, {1.0f, 2.0f, 3.0f}};
    const float inf = std::numeric_limits<float>::infinity();
    float entry = -1.0f;
    // Straight at a face, along -z (x and y directions zero: infinite inverses).
    CHECK(stoa::rayHitsBox(stoa::makeRay({0.5f, 0.5f, 10.0f}, {0.0f, 0.0f, -1.0f}), box, inf, entry));
    CHECK(entry == Approx(7.0f));
    // The same with the direction twice as long: t halves.
    CHECK(stoa::rayHitsBox(stoa::makeRay({0.5f, 0.5f, 10.0f}, {0.0f, 0.0f, -2.0f}), box, inf, entry));
    CHECK(entry == Approx(3.5f));
    // Along -x, from the +x side, and along +y from below.
    CHECK(stoa::rayHitsBox(stoa::makeRay({5.0f, 1.0f, 2.0f}, {-1.0f, 0.0f, 0.0f}), box, inf, entry));
    CHECK(entry == Approx(4.0f));
    CHECK(stoa::rayHitsBox(stoa::makeRay({0.0f, -6.0f, 0.0f}, {0.0f, 1.0f, 0.0f}), box, inf, entry));
    CHECK(entry == Approx(4.0f));
    // Axis-parallel beside the box: a miss, whichever way.
    CHECK_FALSE(stoa::rayHitsBox(stoa::makeRay({1.5f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}), box, inf, entry));
    CHECK_FALSE(stoa::rayHitsBox(stoa::makeRay({0.0f, 2.5f, -10.0f}, {0.0f, 0.0f, 1.0f}), box, inf, entry));
    // Pointing away.
    CHECK_FALSE(stoa::rayHitsBox(stoa::makeRay({0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, 1.0f}), box, inf, entry));
    CHECK_FALSE(stoa::rayHitsBox(stoa::makeRay({4.0f, 5.0f, 6.0f}, glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f))), box, inf, entry));
    // tMax short of the box; just past it.
    CHECK_FALSE(stoa::rayHitsBox(stoa::makeRay({0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}), box, 6.5f, entry));
    CHECK(stoa::rayHitsBox(stoa::makeRay({0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}), box, 7.5f, entry));
    // From inside: entry 0, whatever the direction, even with tMax tiny.
    entry = -1.0f;
    CHECK(stoa::rayHitsBox(stoa::makeRay({0.2f, -1.0f, 2.0f}, glm::normalize(glm::vec3(-1.0f, 2.0f, 0.5f))), box, inf, entry));
    CHECK(entry == 0.0f);
    entry = -1.0f;
    CHECK(stoa::rayHitsBox(stoa::makeRay({0.2f, -1.0f, 2.0f}, {0.0f, 0.0f, 1.0f}), box, 0.01f, entry));
    CHECK(entry == 0.0f);
    // Diagonal, from the (-,-,-) corner's side: the nearest face decides the entry.
    CHECK(stoa::rayHitsBox(stoa::makeRay({-3.0f, -3.0f, -4.0f}, {1.0f, 1.0f, 1.0f}), box, inf, entry));
    CHECK(entry == Approx(2.0f));   // x enters at 2 (y at 1, z at 1)
    // Negative directions on every axis (slabs crossed max face first).
    CHECK(stoa::rayHitsBox(stoa::makeRay({3.0f, 3.0f, 4.0f}, {-1.0f, -1.0f, -1.0f}), box, inf, entry));
    CHECK(entry == Approx(2.0f));
    // The ray's line meets the box, but behind the origin.
    CHECK_FALSE(stoa::rayHitsBox(stoa::makeRay({3.0f, 3.0f, 4.0f}, {1.0f, 1.0f, 1.0f}), box, inf, entry));
}

// --- rays.cpp: rayHitsTriangle ------------------------------------------------

TEST_CASE("Lab 07: rayHitsTriangle agrees with the plane and barycentric areas for thousands of random rays",
          "[lab07][picking]") {
    Random random(77);
    int compared = 0, hits = 0, misses = 0, beyondHitT = 0, backFacing = 0, outsideEdgeSum = 0, skipped = 0;
    int wrongVerdict = 0, wrongValues = 0, changedOnMiss = 0, illConditioned = 0;
    std::string firstProblem;
    for (int trial = 0; trial < 20000; ++trial) {
        Triangle triangle;
        triangle.p0 = random.inBox(glm::vec3(-5.0f), glm::vec3(5.0f));
        triangle.p1 = random.inBox(glm::vec3(-5.0f), glm::vec3(5.0f));
        triangle.p2 = random.inBox(glm::vec3(-5.0f), glm::vec3(5.0f));
        const glm::vec3 origin = random.inBox(glm::vec3(-15.0f), glm::vec3(15.0f));
        glm::vec3 direction;
        if (trial % 4 != 3) {
            // Towards a point of the triangle's plane: half inside the triangle, half near it.
            float a = random.uniform(-0.3f, 1.3f), b = random.uniform(-0.3f, 1.3f);
            if (trial % 2 == 0) {
                a = random.uniform(0.0f, 1.0f), b = random.uniform(0.0f, 1.0f);
                if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
            }
            direction = glm::normalize(triangle.p0 + a * (triangle.p1 - triangle.p0) + b * (triangle.p2 - triangle.p0) - origin);
        } else {
            direction = random.unitVector();
        }
        if (trial % 5 == 2) direction *= random.uniform(0.2f, 5.0f);
        const Ray ray = stoa::makeRay(origin, direction);
        const ReferenceHit expected = referenceIntersect(ray, triangle);
        // Near an edge, nearly parallel, or too near the origin: left out.
        if (!expected.crosses || std::abs(expected.margin()) < 1e-4 || expected.cosine < 1e-2 || std::abs(expected.t) < 1e-3) {
            ++skipped;
            continue;
        }
        Hit hit;
        // A third of the time an earlier hit already stands, nearer or further.
        const bool earlier = trial % 3 == 1;
        if (earlier) {
            hit.t = static_cast<float>(std::abs(expected.t)) * random.uniform(0.3f, 1.7f);
            if (std::abs(hit.t - expected.t) < 1e-3 * std::abs(expected.t)) {
                ++skipped;
                continue;
            }
            hit.triangle = 12;
            hit.u = 0.125f;
            hit.v = 0.25f;
        }
        const Hit before = hit;
        ++compared;
        const bool inside = expected.margin() > 0.0;
        const bool shouldHit = inside && expected.t > 0.0 && expected.t < before.t;
        if (inside && expected.t > 0.0 && !shouldHit) ++beyondHitT;
        if (shouldHit && glm::dot(glm::dvec3(direction), glm::cross(glm::dvec3(triangle.p1 - triangle.p0),
                                                                    glm::dvec3(triangle.p2 - triangle.p0))) > 0.0)
            ++backFacing;
        if (!inside && expected.u > 0.0 && expected.v > 0.0) ++outsideEdgeSum;
        const bool result = stoa::rayHitsTriangle(ray, triangle, hit);
        if (result != shouldHit) {
            ++wrongVerdict;
            if (firstProblem.empty())
                firstProblem = std::string(result ? "a hit" : "a miss") + " where t " + std::to_string(expected.t) + ", u " +
                               std::to_string(expected.u) + ", v " + std::to_string(expected.v) + " (hit.t was " +
                               std::to_string(before.t) + "), triangle " + describe(triangle.p0) + " " + describe(triangle.p1) +
                               " " + describe(triangle.p2) + ", " + describe(ray);
            continue;
        }
        if (shouldHit) {
            ++hits;
            // u, v within 1e-4, or float's rounding where the case is ill-conditioned
            // (the solution's error stays under 1.6e-7 times the condition).
            const double condition = conditioning(glm::dvec3(ray.origin), glm::dvec3(ray.direction), ReferenceTriangle(triangle));
            const double uvTolerance = std::max(1e-4, 5e-7 * condition);
            if (condition > 200.0) ++illConditioned;
            const bool ok = std::abs(hit.t - expected.t) <= 1e-4 * expected.t && std::abs(hit.u - expected.u) <= uvTolerance &&
                            std::abs(hit.v - expected.v) <= uvTolerance && hit.triangle == before.triangle;
            if (!ok) {
                ++wrongValues;
                if (firstProblem.empty())
                    firstProblem = "t, u, v " + std::to_string(hit.t) + ", " + std::to_string(hit.u) + ", " + std::to_string(hit.v) +
                                   " where they are " + std::to_string(expected.t) + ", " + std::to_string(expected.u) + ", " +
                                   std::to_string(expected.v) + " (and hit.triangle must stay as it was)";
            }
        } else {
            ++misses;
            if (hit.t != before.t || hit.u != before.u || hit.v != before.v || hit.triangle != before.triangle) {
                ++changedOnMiss;
                if (firstProblem.empty()) firstProblem = "a miss changed the hit";
            }
        }
    }
    INFO(firstProblem);
    INFO(compared << " compared (" << hits << " hits, " << misses << " misses, " << beyondHitT << " beyond hit.t, "
                  << backFacing << " hits from behind, " << outsideEdgeSum << " past the third edge), " << skipped
                  << " left out at a margin, " << illConditioned << " hits ill-conditioned (u, v within 5e-7 times the condition)");
    CHECK(wrongVerdict == 0);
    CHECK(wrongValues == 0);
    CHECK(changedOnMiss == 0);
    CHECK(hits > 3000);
    CHECK(misses > 3000);
    CHECK(beyondHitT > 500);
    CHECK(backFacing > 1000);
    CHECK(outsideEdgeSum > 500);
    CHECK(skipped < 2000);
}

TEST_CASE("Lab 07: rayHitsTriangle hits both faces, keeps a nearer hit and misses parallel rays", "[lab07][picking]") {
    const Triangle triangle{{0.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 2.0f}, {0.0f, 2.0f, 0.0f}, 3};
    const glm::vec3 normal = glm::normalize(glm::cross(triangle.p1 - triangle.p0, triangle.p2 - triangle.p0));   // (-1, 0, 1)/sqrt2
    const glm::vec3 point = triangle.p0 + 0.25f * (triangle.p1 - triangle.p0) + 0.5f * (triangle.p2 - triangle.p0);
    // From the front and from behind: the same point, u and v.
    for (const float side : {1.0f, -1.0f}) {
        INFO("side " << side);
        Hit hit;
        CHECK(stoa::rayHitsTriangle(stoa::makeRay(point + side * 3.0f * normal, -side * normal), triangle, hit));
        CHECK(hit.t == Approx(3.0f).epsilon(1e-5));
        CHECK(hit.u == Approx(0.25f).epsilon(1e-5));
        CHECK(hit.v == Approx(0.5f).epsilon(1e-5));
        CHECK(hit.triangle == -1);   // the caller sets it
    }
    // A hit beyond hit.t is no hit, and leaves it as it was.
    {
        Hit hit;
        hit.t = 2.5f;
        hit.triangle = 9;
        hit.u = 0.1f;
        hit.v = 0.2f;
        CHECK_FALSE(stoa::rayHitsTriangle(stoa::makeRay(point + 3.0f * normal, -normal), triangle, hit));
        CHECK(hit.t == 2.5f);
        CHECK(hit.triangle == 9);
        CHECK(hit.u == 0.1f);
        CHECK(hit.v == 0.2f);
        hit.t = 3.5f;
        CHECK(stoa::rayHitsTriangle(stoa::makeRay(point + 3.0f * normal, -normal), triangle, hit));
        CHECK(hit.t == Approx(3.0f).epsilon(1e-5));
    }
    // Behind the origin: no hit.
    {
        Hit hit;
        CHECK_FALSE(stoa::rayHitsTriangle(stoa::makeRay(point + 3.0f * normal, normal), triangle, hit));
        CHECK_FALSE(hit.found());
        CHECK(hit.t == std::numeric_limits<float>::infinity());
    }
    // Parallel to the triangle: above its plane, and in it.
    for (const glm::vec3& direction : {glm::vec3(1.0f, 0.0f, 1.0f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(-1.0f, -1.0f, -1.0f)}) {
        INFO("direction " << describe(direction));
        Hit hit;
        CHECK_FALSE(stoa::rayHitsTriangle(stoa::makeRay(point + normal - 2.0f * direction, direction), triangle, hit));
        CHECK_FALSE(stoa::rayHitsTriangle(stoa::makeRay(point - 3.0f * direction, direction), triangle, hit));
        CHECK(hit.t == std::numeric_limits<float>::infinity());
    }
    // Just outside each edge (u < 0, v < 0, u + v > 1), and just inside.
    const std::array<glm::vec2, 3> outside = {glm::vec2(-0.01f, 0.5f), glm::vec2(0.5f, -0.01f), glm::vec2(0.51f, 0.5f)};
    const std::array<glm::vec2, 3> inside = {glm::vec2(0.01f, 0.5f), glm::vec2(0.5f, 0.01f), glm::vec2(0.49f, 0.5f)};
    for (std::size_t i = 0; i < 3; ++i) {
        INFO("edge " << i);
        const auto at = [&](const glm::vec2& uv) {
            return triangle.p0 + uv.x * (triangle.p1 - triangle.p0) + uv.y * (triangle.p2 - triangle.p0);
        };
        Hit hit;
        CHECK_FALSE(stoa::rayHitsTriangle(stoa::makeRay(at(outside[i]) + 2.0f * normal, -normal), triangle, hit));
        CHECK(stoa::rayHitsTriangle(stoa::makeRay(at(inside[i]) + 2.0f * normal, -normal), triangle, hit));
        CHECK(hit.u == Approx(inside[i].x).margin(1e-5));
        CHECK(hit.v == Approx(inside[i].y).margin(1e-5));
    }
}

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
