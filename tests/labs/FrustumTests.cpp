// Lab 06's frustum (frustum.cpp) against independent references:
//   - the frustum's planes against planes built from its 8 corners (the NDC cube
//     unprojected through the inverse matrix in double, each side from three
//     corners and a cross product, oriented towards the corners' centre);
//   - the sphere and box tests against brute force with those planes, for
//     thousands of random spheres and boxes, and the cases a wrong test gets wrong
//     (a box around the whole frustum, a sphere across one plane).
// The mistakes of solutions/06_culling/mistakes/ in frustum.cpp each fail at
// least one case here. BoundsTests.cpp and LodTests.cpp test the rest of the
// lab's culling and level-of-detail math.

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab06.hpp"

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
using stoa::BoundingSphere;
using stoa::Frustum;

namespace {

using Random = stoa::test::Random;

// --- the reference frustum: from the corners -------------------------------

struct ReferencePlane {
    glm::dvec3 normal{0.0};   // unit, inwards
    double d = 0.0;           // normal . p + d = signed distance
    double distance(const glm::dvec3& p) const { return glm::dot(normal, p) + d; }
};

struct ReferenceFrustum {
    std::array<glm::dvec3, 8> corners;   // index bits: x (1), y (2), z (4); bit set = +1 in NDC
    glm::dvec3 center{0.0};
    std::array<ReferencePlane, 6> planes;   // Left, Right, Bottom, Top, Near, Far
    glm::dvec3 low{0.0}, high{0.0};         // the corners' box
    double size = 0.0;                      // the box's diagonal
};

ReferenceFrustum referenceFrustum(const glm::mat4& viewProjection) {
    ReferenceFrustum frustum;
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(viewProjection));
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 ndc((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
        const glm::dvec4 world = inverse * ndc;
        frustum.corners[i] = glm::dvec3(world) / world.w;
        frustum.center += frustum.corners[i] / 8.0;
    }
    frustum.low = frustum.high = frustum.corners[0];
    for (const glm::dvec3& corner : frustum.corners) {
        frustum.low = glm::min(frustum.low, corner);
        frustum.high = glm::max(frustum.high, corner);
    }
    frustum.size = glm::distance(frustum.low, frustum.high);
    // Side s lies where NDC axis s / 2 is -1 (even s) or +1 (odd s): the four
    // corners with that bit; three of them make the plane.
    for (int side = 0; side < 6; ++side) {
        const int bit = 1 << (side / 2);
        const int value = (side % 2) ? bit : 0;
        std::vector<glm::dvec3> face;
        for (int i = 0; i < 8; ++i)
            if ((i & bit) == value) face.push_back(frustum.corners[i]);
        // face[0], face[1], face[3]: two edges of the quad from face[0], whatever the bit.
        glm::dvec3 normal = glm::normalize(glm::cross(face[1] - face[0], face[3] - face[0]));
        if (glm::dot(normal, frustum.center - face[0]) < 0.0) normal = -normal;
        frustum.planes[side] = {normal, -glm::dot(normal, face[0])};
    }
    return frustum;
}

// A camera to test against: its projection, view, and the names of its axes.
struct TestCamera {
    std::string name;
    glm::mat4 projection;
    glm::mat4 view;
    bool perspective = true;
    glm::mat4 viewProjection() const { return projection * view; }
    glm::vec3 right() const { return {view[0][0], view[1][0], view[2][0]}; }
    glm::vec3 up() const { return {view[0][1], view[1][1], view[2][1]}; }
    glm::vec3 forward() const { return -glm::vec3(view[0][2], view[1][2], view[2][2]); }
};

std::vector<TestCamera> testCameras() {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    return {
        {"perspective 60 deg, 16:9, near 0.1 far 100",
         glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f), glm::lookAt(glm::vec3(0, 2, 5), glm::vec3(0, 1, 0), up), true},
        {"perspective 35 deg, square, near 1 far 500, off the origin",
         glm::perspective(glm::radians(35.0f), 1.0f, 1.0f, 500.0f), glm::lookAt(glm::vec3(30, 10, -20), glm::vec3(0, 0, 0), up), true},
        {"perspective 90 deg, tall, looking almost straight down",
         glm::perspective(glm::radians(90.0f), 0.5f, 0.5f, 60.0f), glm::lookAt(glm::vec3(1, 40, 2), glm::vec3(0, 0, 0), up), true},
        {"perspective 25 deg, wide, looking up and back",
         glm::perspective(glm::radians(25.0f), 2.4f, 0.3f, 80.0f), glm::lookAt(glm::vec3(-4, 1, 9), glm::vec3(-10, 12, 30), up), true},
        {"asymmetric perspective (glm::frustum)",
         glm::frustum(-0.2f, 0.6f, -0.1f, 0.3f, 0.5f, 40.0f), glm::lookAt(glm::vec3(5, 3, 5), glm::vec3(0, 0, 0), up), true},
        {"orthographic 20 x 10, near 0.1 far 50",
         glm::ortho(-10.0f, 10.0f, -5.0f, 5.0f, 0.1f, 50.0f), glm::lookAt(glm::vec3(3, 4, 5), glm::vec3(0, 0, 0), up), false},
        {"orthographic 80 x 60 from a light, near -20 far 80",
         glm::ortho(-40.0f, 40.0f, -30.0f, 30.0f, -20.0f, 80.0f),
         glm::lookAt(glm::vec3(20, 30, 10), glm::vec3(0, 0, 0), up), false},
        {"asymmetric orthographic",
         glm::ortho(-3.0f, 7.0f, -1.0f, 4.0f, 1.0f, 30.0f), glm::lookAt(glm::vec3(-6, 2, -3), glm::vec3(4, 0, 8), up), false},
    };
}

const char* const kSideNames[6] = {"Left", "Right", "Bottom", "Top", "Near", "Far"};

double distanceTo(const stoa::Plane& plane, const glm::dvec3& p) {
    return glm::dot(glm::dvec3(plane.normal), p) + static_cast<double>(plane.d);
}

// A point on side `side`, inside the frustum's other planes: the centre of the
// side's four corners. Also its distance to the nearest other plane.
glm::dvec3 pointOnSide(const ReferenceFrustum& frustum, int side, double& room) {
    const int bit = 1 << (side / 2);
    const int value = (side % 2) ? bit : 0;
    glm::dvec3 point(0.0);
    for (int i = 0; i < 8; ++i)
        if ((i & bit) == value) point += frustum.corners[i] / 4.0;
    room = std::numeric_limits<double>::max();
    for (int other = 0; other < 6; ++other)
        if (other != side) room = std::min(room, frustum.planes[other].distance(point));
    return point;
}

} // namespace

// --- frustum.cpp ----------------------------------------------------------

TEST_CASE("Lab 06: frustumPlanes agrees with planes built from the frustum's corners", "[lab06][culling]") {
    for (const TestCamera& camera : testCameras()) {
        INFO(camera.name);
        const Frustum frustum = stoa::frustumPlanes(camera.viewProjection());
        const ReferenceFrustum reference = referenceFrustum(camera.viewProjection());
        for (int side = 0; side < 6; ++side) {
            INFO(kSideNames[side] << " plane");
            const stoa::Plane& plane = frustum.planes[side];
            const ReferencePlane& expected = reference.planes[side];
            CHECK(std::abs(glm::length(plane.normal) - 1.0f) <= 1e-5f);
            CHECK(glm::distance(glm::dvec3(plane.normal), expected.normal) <= 1e-3);
            CHECK(std::abs(plane.d - expected.d) <= 1e-3 * std::max(1.0, std::abs(expected.d)));
            // The corners of the side lie on it; the centre of all corners inside.
            for (int i = 0; i < 8; ++i)
                if (((i >> (side / 2)) & 1) == side % 2)
                    CHECK(std::abs(distanceTo(plane, reference.corners[i])) <= 1e-4 * reference.size);
            CHECK(distanceTo(plane, reference.center) > 0.0);
        }
        // The order of Frustum::Side, in the camera's own axes.
        CHECK(glm::dot(frustum.planes[Frustum::Left].normal, camera.right()) > 0.0f);
        CHECK(glm::dot(frustum.planes[Frustum::Right].normal, camera.right()) < 0.0f);
        CHECK(glm::dot(frustum.planes[Frustum::Bottom].normal, camera.up()) > 0.0f);
        CHECK(glm::dot(frustum.planes[Frustum::Top].normal, camera.up()) < 0.0f);
        CHECK(glm::dot(frustum.planes[Frustum::Near].normal, camera.forward()) > 0.0f);
        CHECK(glm::dot(frustum.planes[Frustum::Far].normal, camera.forward()) < 0.0f);
        if (!camera.perspective) {   // an orthographic frustum's sides are the camera's axes
            CHECK(glm::dot(frustum.planes[Frustum::Left].normal, camera.right()) == Approx(1.0f).epsilon(1e-5));
            CHECK(glm::dot(frustum.planes[Frustum::Top].normal, camera.up()) == Approx(-1.0f).epsilon(1e-5));
            CHECK(glm::dot(frustum.planes[Frustum::Far].normal, camera.forward()) == Approx(-1.0f).epsilon(1e-5));
        }
    }
}

TEST_CASE("Lab 06: frustumPlanes of the identity is the clip cube", "[lab06][culling]") {
    const Frustum frustum = stoa::frustumPlanes(glm::mat4(1.0f));
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int side = 0; side < 6; ++side) {
        INFO(kSideNames[side]);
        CHECK(glm::distance(frustum.planes[side].normal, normals[side]) <= 1e-6f);
        CHECK(frustum.planes[side].d == Approx(1.0f).epsilon(1e-6));
    }
}

TEST_CASE("Lab 06: sphereInFrustum agrees with brute force over thousands of random spheres",
          "[lab06][culling]") {
    Random random(2024);
    for (const TestCamera& camera : testCameras()) {
        INFO(camera.name);
        const Frustum frustum = stoa::frustumPlanes(camera.viewProjection());
        const ReferenceFrustum reference = referenceFrustum(camera.viewProjection());
        const glm::dvec3 halfSize = (reference.high - reference.low) * 0.5;
        const glm::vec3 low(reference.center - 1.4 * halfSize), high(reference.center + 1.4 * halfSize);
        int kept = 0, dropped = 0, straddling = 0, mismatches = 0, skipped = 0;
        for (int i = 0; i < 3000; ++i) {
            // Mostly small spheres, some large, all about the frustum's box.
            const float sizeShare = i % 4 == 0 ? random.uniform(0.0f, 0.4f) : random.uniform(0.0f, 0.06f);
            const BoundingSphere sphere{random.inBox(low, high), sizeShare * static_cast<float>(reference.size)};
            bool outside = false, crossing = false, ambiguous = false;
            for (const ReferencePlane& plane : reference.planes) {
                const double distance = plane.distance(glm::dvec3(sphere.center));
                if (std::abs(distance + sphere.radius) <= 1e-4 * reference.size) ambiguous = true;
                if (distance < -sphere.radius) outside = true;
                if (distance < 0.0 && distance >= -sphere.radius) crossing = true;
            }
            if (ambiguous) {
                ++skipped;
                continue;
            }
            const bool verdict = stoa::sphereInFrustum(frustum, sphere);
            if (verdict == outside) {
                ++mismatches;
                if (mismatches <= 5)
                    FAIL_CHECK("sphere at " << sphere.center.x << " " << sphere.center.y << " " << sphere.center.z
                                            << " radius " << sphere.radius << ": expected "
                                            << (outside ? "dropped" : "kept"));
            }
            (outside ? dropped : kept) += 1;
            if (!outside && crossing) ++straddling;
        }
        INFO(kept << " kept (" << straddling << " across a plane with the centre outside), " << dropped
                  << " dropped, " << skipped << " too close to call");
        CHECK(mismatches == 0);
        // The draw exercised both verdicts and the spheres that cross a side.
        CHECK(kept >= 300);
        CHECK(dropped >= 300);
        CHECK(straddling >= 50);
        CHECK(skipped <= 30);
    }
}

TEST_CASE("Lab 06: boxInFrustum agrees with brute force over thousands of random boxes", "[lab06][culling]") {
    Random random(1999);
    for (const TestCamera& camera : testCameras()) {
        INFO(camera.name);
        const Frustum frustum = stoa::frustumPlanes(camera.viewProjection());
        const ReferenceFrustum reference = referenceFrustum(camera.viewProjection());
        const glm::dvec3 halfSize = (reference.high - reference.low) * 0.5;
        const glm::vec3 low(reference.center - 1.4 * halfSize), high(reference.center + 1.4 * halfSize);
        int kept = 0, dropped = 0, crossing = 0, mismatches = 0, skipped = 0;
        for (int i = 0; i < 3000; ++i) {
            const glm::vec3 center = random.inBox(low, high);
            const float sizeShare = i % 4 == 0 ? 0.4f : 0.06f;
            const glm::vec3 half = random.inBox(glm::vec3(0.0f), glm::vec3(sizeShare * static_cast<float>(reference.size)));
            const Aabb box{center - half, center + half};
            // Outside a plane iff all 8 corners are; dropped iff outside some plane.
            bool outside = false, ambiguous = false, someCornerOutside = false;
            for (const ReferencePlane& plane : reference.planes) {
                double largest = -std::numeric_limits<double>::max();
                for (int c = 0; c < 8; ++c) {
                    const glm::dvec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                                            (c & 4) ? box.max.z : box.min.z);
                    const double distance = plane.distance(corner);
                    largest = std::max(largest, distance);
                    if (distance < 0.0) someCornerOutside = true;
                }
                if (std::abs(largest) <= 1e-4 * reference.size) ambiguous = true;
                if (largest < 0.0) outside = true;
            }
            if (ambiguous) {
                ++skipped;
                continue;
            }
            const bool verdict = stoa::boxInFrustum(frustum, box);
            if (verdict == outside) {
                ++mismatches;
                if (mismatches <= 5)
                    FAIL_CHECK("box " << box.min.x << " " << box.min.y << " " << box.min.z << " to " << box.max.x << " "
                                      << box.max.y << " " << box.max.z << ": expected " << (outside ? "dropped" : "kept"));
            }
            (outside ? dropped : kept) += 1;
            if (!outside && someCornerOutside) ++crossing;
        }
        INFO(kept << " kept (" << crossing << " with a corner outside), " << dropped << " dropped, " << skipped
                  << " too close to call");
        CHECK(mismatches == 0);
        CHECK(kept >= 300);
        CHECK(dropped >= 300);
        CHECK(crossing >= 100);
        CHECK(skipped <= 30);
    }
}

TEST_CASE("Lab 06: boxInFrustum keeps a box around the whole frustum, though all its corners are outside",
          "[lab06][culling]") {
    for (const TestCamera& camera : testCameras()) {
        INFO(camera.name);
        const Frustum frustum = stoa::frustumPlanes(camera.viewProjection());
        const ReferenceFrustum reference = referenceFrustum(camera.viewProjection());
        const glm::vec3 margin(0.05f * static_cast<float>(reference.size));
        const Aabb box{glm::vec3(reference.low) - margin, glm::vec3(reference.high) + margin};
        // Every corner of the box is outside the frustum (the wrong "all corners
        // outside the frustum" test would drop it), but no one plane has all eight outside.
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                                    (c & 4) ? box.max.z : box.min.z);
            double nearest = std::numeric_limits<double>::max();
            for (const ReferencePlane& plane : reference.planes) nearest = std::min(nearest, plane.distance(corner));
            REQUIRE(nearest < 0.0);
        }
        CHECK(stoa::boxInFrustum(frustum, box));
        // So is a flat slab through the frustum's centre, wider than the frustum.
        const glm::vec3 center(reference.center);
        const Aabb slab{glm::vec3(box.min.x, center.y - 0.01f, box.min.z), glm::vec3(box.max.x, center.y + 0.01f, box.max.z)};
        CHECK(stoa::boxInFrustum(frustum, slab));
        CHECK(stoa::sphereInFrustum(frustum, {center, 2.0f * static_cast<float>(reference.size)}));
    }
}

TEST_CASE("Lab 06: a sphere across exactly one plane is kept, one beyond it by more than its radius is dropped",
          "[lab06][culling]") {
    for (const TestCamera& camera : testCameras()) {
        INFO(camera.name);
        const Frustum frustum = stoa::frustumPlanes(camera.viewProjection());
        const ReferenceFrustum reference = referenceFrustum(camera.viewProjection());
        for (int side = 0; side < 6; ++side) {
            INFO(kSideNames[side] << " plane");
            double room = 0.0;
            const glm::dvec3 point = pointOnSide(reference, side, room);
            const double radius = 0.4 * room;   // crosses no other plane
            const glm::dvec3 outward = -reference.planes[side].normal;
            // The centre outside, 0.9 r beyond the plane: the sphere still reaches in.
            const BoundingSphere across{glm::vec3(point + 0.9 * radius * outward), static_cast<float>(radius)};
            CHECK(stoa::sphereInFrustum(frustum, across));
            // Centre inside, near the plane.
            const BoundingSphere inside{glm::vec3(point - 0.5 * radius * outward), static_cast<float>(radius)};
            CHECK(stoa::sphereInFrustum(frustum, inside));
            // 1.1 r beyond: wholly outside.
            const BoundingSphere beyond{glm::vec3(point + 1.1 * radius * outward), static_cast<float>(radius)};
            CHECK_FALSE(stoa::sphereInFrustum(frustum, beyond));
            // The same with boxes: a cube of half-side r/2 across the plane, and one beyond it.
            const float h = static_cast<float>(0.5 * radius);
            const glm::vec3 crossingCenter(point + 0.2 * radius * outward);
            CHECK(stoa::boxInFrustum(frustum, {crossingCenter - h, crossingCenter + h}));
            const glm::vec3 beyondCenter(point + 0.9 * radius * outward);   // sqrt(3) h < 0.9 r: every corner beyond
            CHECK_FALSE(stoa::boxInFrustum(frustum, {beyondCenter - h, beyondCenter + h}));
        }
    }
}
