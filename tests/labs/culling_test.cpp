// Lab 06's culling and level-of-detail math against independent references:
//   - bounding spheres against the mesh's vertices (and the framework's boundsOf()),
//     world spheres against every vertex carried by random TRS matrices (in double);
//   - the frustum's planes against planes built from its 8 corners (the NDC cube
//     unprojected through the inverse matrix in double, each side from three
//     corners and a cross product, oriented towards the corners' centre);
//   - the sphere and box tests against brute force with those planes, for
//     thousands of random spheres and boxes, and the cases a wrong test gets wrong
//     (a box around the whole frustum, a sphere across one plane);
//   - the projected size against glm::perspective: the point one radius above the
//     centre, projected, in pixels;
//   - the level bands.
// The mistakes of solutions/06_culling/mistakes/ each fail at least one case here
// (the two skybox ones are GLSL, left to the image cases).

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab06.hpp"

#include <stoa/geometry/Bounds.hpp>
#include <stoa/geometry/Mesh.hpp>
#include <stoa/geometry/Shapes.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

using stoa::Aabb;
using stoa::BoundingSphere;
using stoa::Frustum;
using stoa::Mesh;

namespace {

using Random = stoa::test::Random;

Mesh meshOf(const std::vector<glm::vec3>& positions) {
    Mesh mesh;
    for (const glm::vec3& position : positions) {
        stoa::Vertex vertex;
        vertex.position = position;
        mesh.vertices.push_back(vertex);
    }
    return mesh;
}

// Points crowded near the origin, one far off on a diagonal and one on the other
// side: the box's centre (3.05, 1.4, -0.7) is far from the points' mean.
Mesh lopsidedMesh() {
    Random random(11);
    std::vector<glm::vec3> points;
    for (int i = 0; i < 200; ++i) points.push_back(random.inBox({-0.5f, -0.2f, -0.3f}, {0.5f, 0.2f, 0.3f}));
    points.push_back({7.0f, 3.0f, -2.0f});
    points.push_back({-0.9f, 0.4f, 0.6f});
    return meshOf(points);
}

// The reference sphere of a mesh, in double: the box's centre and the largest
// distance from it.
struct ReferenceSphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

ReferenceSphere referenceSphere(const Mesh& mesh) {
    ReferenceSphere sphere;
    if (mesh.vertices.empty()) return sphere;
    glm::dvec3 low(std::numeric_limits<double>::max()), high(-std::numeric_limits<double>::max());
    for (const stoa::Vertex& vertex : mesh.vertices) {
        for (int axis = 0; axis < 3; ++axis) {
            low[axis] = std::min(low[axis], static_cast<double>(vertex.position[axis]));
            high[axis] = std::max(high[axis], static_cast<double>(vertex.position[axis]));
        }
    }
    sphere.center = (low + high) * 0.5;
    for (const stoa::Vertex& vertex : mesh.vertices)
        sphere.radius = std::max(sphere.radius, glm::distance(glm::dvec3(vertex.position), sphere.center));
    return sphere;
}

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

// The projected radius in pixels, through glm: a camera at `eye` looking at the
// sphere's centre; the point one radius above the centre (along the camera's
// up) projected; the NDC y difference times half the viewport's height.
double projectedRadiusPixels(const BoundingSphere& sphere, const glm::vec3& eye, float fovYDegrees, int height) {
    const glm::dvec3 center(sphere.center), from(eye);
    glm::dvec3 upHint(0.0, 1.0, 0.0);
    if (std::abs(glm::dot(glm::normalize(center - from), upHint)) > 0.99) upHint = glm::dvec3(1.0, 0.0, 0.0);
    const glm::dmat4 view = glm::lookAt(from, center, upHint);
    const glm::dmat4 projection = glm::perspective(glm::radians(static_cast<double>(fovYDegrees)), 1.5, 0.01, 1e5);
    const glm::dvec3 cameraUp(view[0][1], view[1][1], view[2][1]);
    const auto ndcY = [&](const glm::dvec3& p) {
        const glm::dvec4 clip = projection * view * glm::dvec4(p, 1.0);
        return clip.y / clip.w;
    };
    const double dy = ndcY(center + static_cast<double>(sphere.radius) * cameraUp) - ndcY(center);
    return dy * 0.5 * height;
}

double expectedQuality(double pixels, const stoa::LodSettings& settings) {
    const double q = (pixels - settings.hiddenBelowPixels) / (settings.fullDetailPixels - settings.hiddenBelowPixels);
    return std::clamp(q, 0.0, 1.0);
}

} // namespace

// --- bounds.cpp -----------------------------------------------------------

TEST_CASE("Lab 06: meshBoundingSphere holds every vertex, centred on the box, radius to the furthest",
          "[lab06][culling]") {
    const std::vector<std::pair<std::string, Mesh>> meshes = {
        {"sphere r 0.5", stoa::shapes::sphere(0.5f, 18, 12)},
        {"cube 2", stoa::shapes::cube(2.0f)},
        {"off-centre sphere", [] {
             Mesh mesh = stoa::shapes::sphere(1.5f, 24, 16);
             for (stoa::Vertex& vertex : mesh.vertices) vertex.position += glm::vec3(10.0f, -3.0f, 4.0f);
             return mesh;
         }()},
        {"lopsided points", lopsidedMesh()},
        {"one vertex", meshOf({{2.0f, -1.0f, 3.0f}})},
    };
    for (const auto& [name, mesh] : meshes) {
        INFO(name);
        const BoundingSphere sphere = stoa::meshBoundingSphere(mesh);
        const ReferenceSphere reference = referenceSphere(mesh);
        const double scale = std::max(1.0, glm::length(reference.center));
        for (const stoa::Vertex& vertex : mesh.vertices)
            CHECK(glm::distance(glm::dvec3(vertex.position), glm::dvec3(sphere.center)) <=
                  sphere.radius * (1.0 + 1e-5) + 1e-6 * scale);
        CHECK(glm::distance(glm::dvec3(sphere.center), reference.center) <= 1e-5 * scale);
        CHECK(std::abs(sphere.radius - reference.radius) <= 1e-5 * std::max(1.0, reference.radius));
        // The framework computes the same sphere for the meshes it uploads.
        const BoundingSphere framework = stoa::boundsOf(mesh).sphere;
        CHECK(glm::distance(sphere.center, framework.center) <= 1e-5f * static_cast<float>(scale));
        CHECK(std::abs(sphere.radius - framework.radius) <= 1e-5f * std::max(1.0f, framework.radius));
    }
    // The lopsided set: the box's centre, not the mean, and not the sphere through the far point alone.
    const BoundingSphere lopsided = stoa::meshBoundingSphere(lopsidedMesh());
    CHECK(glm::distance(lopsided.center, glm::vec3(3.05f, 1.4f, -0.7f)) < 0.05f);
    CHECK(lopsided.radius == Approx(glm::distance(glm::vec3(3.05f, 1.4f, -0.7f), glm::vec3(7.0f, 3.0f, -2.0f))).epsilon(0.02));
    // Sphere r 0.5 and cube of side 2: the radius is known.
    CHECK(stoa::meshBoundingSphere(stoa::shapes::sphere(0.5f, 18, 12)).radius == Approx(0.5f).epsilon(1e-4));
    CHECK(stoa::meshBoundingSphere(stoa::shapes::cube(2.0f)).radius == Approx(std::sqrt(3.0f)).epsilon(1e-5));
}

TEST_CASE("Lab 06: meshBoundingSphere of a mesh without vertices is a point at the origin", "[lab06][culling]") {
    const BoundingSphere sphere = stoa::meshBoundingSphere(Mesh{});
    CHECK(sphere.radius == 0.0f);
    CHECK(sphere.center == glm::vec3(0.0f));
}

TEST_CASE("Lab 06: worldBoundingSphere holds every transformed vertex for random TRS matrices",
          "[lab06][culling]") {
    const std::vector<Mesh> meshes = {stoa::shapes::cube(1.0f), stoa::shapes::sphere(0.7f, 16, 10), lopsidedMesh()};
    Random random(6);
    int checked = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const glm::vec3 translation = random.inBox(glm::vec3(-100.0f), glm::vec3(100.0f));
        const glm::vec3 axis = random.unitVector();
        const float angle = random.uniform(-3.14159f, 3.14159f);
        // Non-uniform scales, the extremes 0.3 and 3 among them.
        glm::vec3 scale = random.inBox(glm::vec3(0.3f), glm::vec3(3.0f));
        if (trial % 3 == 0) scale[trial % 9 / 3] = 3.0f;
        if (trial % 4 == 1) scale[(trial / 4) % 3] = 0.3f;
        if (trial % 7 == 2) scale = glm::vec3(0.3f, 3.0f, 1.0f);
        glm::mat4 model = glm::translate(glm::mat4(1.0f), translation);
        model = glm::rotate(model, angle, axis);
        model = glm::scale(model, scale);
        const Mesh& mesh = meshes[trial % meshes.size()];
        const BoundingSphere object = stoa::meshBoundingSphere(mesh);
        const BoundingSphere world = stoa::worldBoundingSphere(object, model);
        INFO("trial " << trial << ", scale " << scale.x << " " << scale.y << " " << scale.z);
        const glm::dmat4 exact(model);
        const double slack = 1e-5 * (1.0 + glm::length(glm::dvec3(world.center)));
        double furthest = 0.0;
        for (const stoa::Vertex& vertex : mesh.vertices) {
            const glm::dvec3 moved(exact * glm::dvec4(glm::dvec3(vertex.position), 1.0));
            furthest = std::max(furthest, glm::distance(moved, glm::dvec3(world.center)));
            ++checked;
        }
        CHECK(furthest <= world.radius * (1.0 + 1e-5) + slack);
        // The centre is the object's centre as a point; the radius scaled by the largest axis scale.
        const glm::dvec3 center(exact * glm::dvec4(glm::dvec3(object.center), 1.0));
        CHECK(glm::distance(center, glm::dvec3(world.center)) <= slack);
        const float largest = std::max({scale.x, scale.y, scale.z});
        CHECK(world.radius == Approx(object.radius * largest).epsilon(1e-5));
    }
    CHECK(checked > 1000);
}

TEST_CASE("Lab 06: worldBoundingSphere: a uniform scale scales the radius, a translation moves only the centre",
          "[lab06][culling]") {
    const BoundingSphere object{{0.5f, -1.0f, 2.0f}, 1.25f};
    for (const float s : {0.3f, 1.0f, 2.0f, 3.0f, 10.0f}) {
        INFO("scale " << s);
        const BoundingSphere scaled = stoa::worldBoundingSphere(object, glm::scale(glm::mat4(1.0f), glm::vec3(s)));
        CHECK(scaled.radius == Approx(object.radius * s).epsilon(1e-6));
        CHECK(glm::distance(scaled.center, object.center * s) <= 1e-5f * s);
        // Rotated too: still s times.
        const glm::mat4 rotated = glm::scale(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3))), glm::vec3(s));
        CHECK(stoa::worldBoundingSphere(object, rotated).radius == Approx(object.radius * s).epsilon(1e-5));
    }
    const glm::vec3 offset(12.0f, -3.5f, 40.0f);
    const BoundingSphere moved = stoa::worldBoundingSphere(object, glm::translate(glm::mat4(1.0f), offset));
    CHECK(moved.radius == object.radius);
    CHECK(glm::distance(moved.center, object.center + offset) <= 1e-5f);
    const BoundingSphere same = stoa::worldBoundingSphere(object, glm::mat4(1.0f));
    CHECK(same.radius == object.radius);
    CHECK(same.center == object.center);
}

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

// --- level_of_detail.cpp ----------------------------------------------------

TEST_CASE("Lab 06: lodQuality agrees with the projected radius through glm::perspective", "[lab06][lod]") {
    Random random(77);
    const stoa::LodSettings defaults;
    const std::vector<stoa::LodSettings> settingsList = {defaults, {0.0f, 40.0f}, {5.0f, 200.0f}};
    int inRange = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const stoa::LodSettings& settings = settingsList[trial % settingsList.size()];
        const float fov = random.uniform(20.0f, 100.0f);
        const int height = 240 + static_cast<int>(random.uniform(0.0f, 1200.0f));
        const glm::vec3 eye = random.inBox(glm::vec3(-50.0f), glm::vec3(50.0f));
        const float distance = random.uniform(2.0f, 300.0f);
        // Small r / d (at most 0.1), where the formula and the projection agree.
        const float radius = distance * random.uniform(0.0005f, 0.1f);
        const BoundingSphere sphere{eye + distance * random.unitVector(), radius};
        const double pixels = projectedRadiusPixels(sphere, eye, fov, height);
        const double expected = expectedQuality(pixels, settings);
        const float quality = stoa::lodQuality(sphere, eye, fov, height, settings);
        INFO("trial " << trial << ": fov " << fov << ", height " << height << ", r " << radius << ", d " << distance
                      << ", " << pixels << " px");
        CHECK(quality >= 0.0f);
        CHECK(quality <= 1.0f);
        CHECK(std::abs(quality - expected) <= 0.01 * std::max(expected, 0.01));
        if (expected > 0.02 && expected < 0.98) ++inRange;
    }
    CHECK(inRange >= 150);   // most draws land between the two thresholds
}

TEST_CASE("Lab 06: lodQuality is 0 at hiddenBelowPixels, 1 at fullDetailPixels, linear between, clamped",
          "[lab06][lod]") {
    const float fov = 50.0f;
    const int height = 720;
    const glm::vec3 eye(3.0f, 1.7f, -4.0f);
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, -0.2f, 2.0f));
    const float radius = 1.5f;
    const double pixelsPerRadiusOverDistance = 0.5 * height / std::tan(0.5 * glm::radians(static_cast<double>(fov)));
    // The distance at which the sphere's projected radius is `pixels`.
    const auto at = [&](double pixels) {
        const float distance = static_cast<float>(pixelsPerRadiusOverDistance * radius / pixels);
        return BoundingSphere{eye + distance * direction, radius};
    };
    for (const stoa::LodSettings& settings : {stoa::LodSettings{}, stoa::LodSettings{10.0f, 50.0f}}) {
        INFO("hidden " << settings.hiddenBelowPixels << ", full " << settings.fullDetailPixels);
        CHECK(stoa::lodQuality(at(settings.hiddenBelowPixels), eye, fov, height, settings) == Approx(0.0f).margin(1e-4));
        CHECK(stoa::lodQuality(at(settings.fullDetailPixels), eye, fov, height, settings) == Approx(1.0f).margin(1e-4));
        const double middle = 0.5 * (settings.hiddenBelowPixels + settings.fullDetailPixels);
        CHECK(stoa::lodQuality(at(middle), eye, fov, height, settings) == Approx(0.5f).margin(1e-4));
        const double quarter = settings.hiddenBelowPixels + 0.25 * (settings.fullDetailPixels - settings.hiddenBelowPixels);
        CHECK(stoa::lodQuality(at(quarter), eye, fov, height, settings) == Approx(0.25f).margin(1e-4));
        // Beyond the thresholds: clamped.
        CHECK(stoa::lodQuality(at(0.5 * settings.hiddenBelowPixels + 0.01), eye, fov, height, settings) == 0.0f);
        CHECK(stoa::lodQuality(at(3.0 * settings.fullDetailPixels), eye, fov, height, settings) == 1.0f);
        CHECK(stoa::lodQuality({eye + 1e5f * direction, radius}, eye, fov, height, settings) == 0.0f);
        // Just outside the sphere: huge on the screen, still 1.
        CHECK(stoa::lodQuality({eye + 1.01f * radius * direction, radius}, eye, fov, height, settings) == 1.0f);
    }
}

TEST_CASE("Lab 06: lodQuality is 1 with the eye inside the sphere, its centre included", "[lab06][lod]") {
    const glm::vec3 eye(10.0f, 2.0f, -7.0f);
    CHECK(stoa::lodQuality({eye, 0.5f}, eye, 60.0f, 720) == 1.0f);
    CHECK(stoa::lodQuality({eye + glm::vec3(0.3f, 0.0f, 0.0f), 0.5f}, eye, 60.0f, 720) == 1.0f);
    CHECK(stoa::lodQuality({eye + glm::vec3(0.0f, 0.0f, -4.0f), 4.0f}, eye, 45.0f, 480) == 1.0f);
    // Even with thresholds it could not otherwise reach.
    CHECK(stoa::lodQuality({eye + glm::vec3(0.0f, 1.0f, 0.0f), 2.0f}, eye, 60.0f, 10, {100.0f, 1000.0f}) == 1.0f);
}

TEST_CASE("Lab 06: lodQuality grows with the viewport's height and shrinks with the field of view and distance",
          "[lab06][lod]") {
    const glm::vec3 eye(0.0f);
    const BoundingSphere sphere{{0.0f, 0.0f, -60.0f}, 1.0f};
    const float base = stoa::lodQuality(sphere, eye, 50.0f, 720);
    CHECK(base > 0.0f);
    CHECK(base < 1.0f);
    CHECK(stoa::lodQuality(sphere, eye, 50.0f, 1080) > base);
    CHECK(stoa::lodQuality(sphere, eye, 70.0f, 720) < base);
    CHECK(stoa::lodQuality({{0.0f, 0.0f, -80.0f}, 1.0f}, eye, 50.0f, 720) < base);
    // 0.5 * 720 / tan(25 deg) / 60 = 12.87 px: (12.87 - 2) / 78.
    CHECK(base == Approx((0.5 * 720.0 / std::tan(glm::radians(25.0)) / 60.0 - 2.0) / 78.0).epsilon(1e-4));
}

TEST_CASE("Lab 06: levelOfDetail: -1 for no quality, 0 for full, the bands in between", "[lab06][lod]") {
    for (int levels = 1; levels <= 6; ++levels) {
        INFO(levels << " levels");
        CHECK(stoa::levelOfDetail(0.0f, levels) == -1);
        CHECK(stoa::levelOfDetail(-0.5f, levels) == -1);
        CHECK(stoa::levelOfDetail(-0.0f, levels) == -1);
        CHECK(stoa::levelOfDetail(std::numeric_limits<float>::quiet_NaN(), levels) == -1);
        CHECK(stoa::levelOfDetail(1.0f, levels) == 0);
        CHECK(stoa::levelOfDetail(1e-6f, levels) == levels - 1);
        CHECK(stoa::levelOfDetail(std::numeric_limits<float>::denorm_min(), levels) == levels - 1);
        CHECK(stoa::levelOfDetail(std::numeric_limits<float>::min(), levels) == levels - 1);
        // Monotone: more quality never a coarser level; always a level that exists.
        int previous = stoa::levelOfDetail(1e-7f, levels);
        for (int step = 1; step <= 20000; ++step) {
            const float quality = static_cast<float>(step) / 20000.0f;
            const int level = stoa::levelOfDetail(quality, levels);
            if (level > previous || level < 0 || level >= levels) {
                FAIL_CHECK("quality " << quality << ": level " << level << " after " << previous);
                break;
            }
            previous = level;
        }
        // The independent band: level k for quality in (1 - (k+1)/n, 1 - k/n].
        for (int step = 1; step <= 1000; ++step) {
            const double quality = (step - 0.5) / 1000.0;   // never on a band's edge
            const int expected = std::min(levels - 1, static_cast<int>((1.0 - quality) * levels));
            const int level = stoa::levelOfDetail(static_cast<float>(quality), levels);
            if (level != expected) {
                FAIL_CHECK("quality " << quality << ": level " << level << ", expected " << expected);
                break;
            }
        }
    }
}

// Quality in (0.75, 1] gives level 0, (0.5, 0.75] level 1, (0.25, 0.5] level 2, (0, 0.25] level 3.
TEST_CASE("Lab 06: levelOfDetail with 4 levels: 0 down to 0.75 exclusive, then 1 to 0.5, 2 to 0.25, 3 to 0",
          "[lab06][lod]") {
    CHECK(stoa::levelOfDetail(1.0f, 4) == 0);
    CHECK(stoa::levelOfDetail(0.9f, 4) == 0);
    CHECK(stoa::levelOfDetail(0.7501f, 4) == 0);
    CHECK(stoa::levelOfDetail(0.75f, 4) == 1);
    CHECK(stoa::levelOfDetail(0.6f, 4) == 1);
    CHECK(stoa::levelOfDetail(0.5001f, 4) == 1);
    CHECK(stoa::levelOfDetail(0.5f, 4) == 2);
    CHECK(stoa::levelOfDetail(0.4f, 4) == 2);
    CHECK(stoa::levelOfDetail(0.2501f, 4) == 2);
    CHECK(stoa::levelOfDetail(0.25f, 4) == 3);
    CHECK(stoa::levelOfDetail(0.1f, 4) == 3);
    CHECK(stoa::levelOfDetail(0.0001f, 4) == 3);
    CHECK(stoa::levelOfDetail(0.0f, 4) == -1);
}
