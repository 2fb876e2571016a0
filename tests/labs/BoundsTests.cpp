// Lab 06's bounding spheres (bounds.cpp) against independent references:
//   - bounding spheres against the mesh's vertices (and the framework's boundsOf()),
//     world spheres against every vertex carried by random TRS matrices (in double).
// The mistake of solutions/06_culling/mistakes/ in bounds.cpp fails at least one
// case here. FrustumTests.cpp and LodTests.cpp test the rest of the lab's culling
// and level-of-detail math.

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab06.hpp"

#include <stoa/geometry/Bounds.hpp>
#include <stoa/geometry/Mesh.hpp>
#include <stoa/geometry/Shapes.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

using stoa::BoundingSphere;
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
