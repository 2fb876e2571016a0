// Lab 07's rays against independent references:
//   - rayThroughPixel against glm::perspective * glm::lookAt: the ray starts on the
//     near plane, has unit direction, and a point along it projects back onto the
//     pixel it was cast through (y down); the centre pixel looks forward;
//   - rayHitsBox against the ray's intersections with the box's six face
//     rectangles (in double), for thousands of random rays and boxes, axis-parallel
//     rays (infinite inverse direction components) and origins inside among them;
//   - rayHitsTriangle against the ray's intersection with the triangle's plane and
//     barycentric coordinates from signed areas (in double).
// Cases near a boundary (a ray grazing an edge or a box's face, a hit at tMax) are
// left out of the exact comparisons by a margin, and counted. BvhTests.cpp tests
// the BVH built on these.

#include "catch.hpp"
#include "PickingReferences.hpp"
#include "TestRandom.hpp"

#include "lab07.hpp"

#include <stoa/geometry/Bounds.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using stoa::Aabb;
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
