#include "catch.hpp"
#include "MeshChecks.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <limits>

using namespace stoa;
using stoa::test::near;

namespace {

/// Two triangles sharing the edge 1-2: a unit square in the XY plane facing +Z.
Mesh unitSquare() {
    Mesh mesh;
    mesh.vertices = {{{0, 0, 0}, {0, 0, 1}, {0, 0}},
                     {{1, 0, 0}, {0, 0, 1}, {1, 0}},
                     {{0, 1, 0}, {0, 0, 1}, {0, 1}},
                     {{1, 1, 0}, {0, 0, 1}, {1, 1}}};
    mesh.indices = {0, 1, 2, 2, 1, 3};
    return mesh;
}

/// Runs mesh.validate("bunny.obj") and returns what it threw.
std::string validationError(const Mesh& mesh) {
    try {
        mesh.validate("bunny.obj");
    } catch (const InputError& error) {
        CHECK(error.file() == "bunny.obj");
        CHECK(error.line() == 0);
        return error.what();
    }
    FAIL("Mesh::validate() accepted a broken mesh");
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

} // namespace

TEST_CASE("Mesh counts triangles and measures its bounds", "[geometry][mesh]") {
    Mesh mesh = unitSquare();
    CHECK(mesh.triangleCount() == 2);
    mesh.vertices[3].position = {1, 1, -2};
    const auto [lower, upper] = mesh.bounds();
    CHECK(near(lower, {0, 0, -2}));
    CHECK(near(upper, {1, 1, 0}));
    CHECK(Mesh().triangleCount() == 0);
}

TEST_CASE("Mesh::validate accepts a well-formed mesh", "[geometry][mesh]") {
    CHECK_NOTHROW(unitSquare().validate("square"));
    CHECK_NOTHROW(Mesh().validate("empty"));
}

TEST_CASE("Mesh::validate rejects broken meshes, naming the source", "[geometry][mesh]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();

    SECTION("an index past the last vertex") {
        Mesh mesh = unitSquare();
        mesh.indices[4] = 4;
        const std::string what = validationError(mesh);
        INFO(what);
        CHECK(contains(what, "bunny.obj: "));
        CHECK(contains(what, "triangle 1 refers to vertex 4"));
        CHECK(contains(what, "4 vertices"));
    }
    SECTION("an index count that is not a multiple of 3") {
        Mesh mesh = unitSquare();
        mesh.indices.pop_back();
        const std::string what = validationError(mesh);
        INFO(what);
        CHECK(contains(what, "5 indices"));
        CHECK(contains(what, "multiple of 3"));
    }
    SECTION("a NaN position") {
        Mesh mesh = unitSquare();
        mesh.vertices[2].position.y = nan;
        const std::string what = validationError(mesh);
        INFO(what);
        CHECK(contains(what, "vertex 2 has a position"));
    }
    SECTION("an infinite normal") {
        Mesh mesh = unitSquare();
        mesh.vertices[1].normal.z = -infinity;
        const std::string what = validationError(mesh);
        INFO(what);
        CHECK(contains(what, "vertex 1 has a normal"));
    }
    SECTION("a NaN uv") {
        Mesh mesh = unitSquare();
        mesh.vertices[3].uv.x = nan;
        const std::string what = validationError(mesh);
        INFO(what);
        CHECK(contains(what, "vertex 3 has a uv"));
    }
}

TEST_CASE("computeSmoothNormals weighs each face by its area", "[geometry][mesh]") {
    // Vertex 0 is shared by a triangle of area 2 facing +Y and one of area 1 facing +X:
    //   (p1 - p0) x (p2 - p0) = (0, 0, 2) x (2, 0, 0) = (0, 4, 0)
    //   (p4 - p0) x (p3 - p0) = (0, 0, -2) x (0, 1, 0) = (2, 0, 0)
    Mesh mesh;
    mesh.vertices.resize(6);
    mesh.vertices[0].position = {0, 0, 0};
    mesh.vertices[1].position = {0, 0, 2};
    mesh.vertices[2].position = {2, 0, 0};
    mesh.vertices[3].position = {0, 1, 0};
    mesh.vertices[4].position = {0, 0, -2};
    mesh.vertices[5].position = {5, 5, 5};  // used by no triangle
    mesh.indices = {0, 1, 2, 0, 4, 3};
    computeSmoothNormals(mesh);

    CHECK(near(mesh.vertices[0].normal, glm::normalize(glm::vec3(2, 4, 0))));
    CHECK(near(mesh.vertices[1].normal, {0, 1, 0}));
    CHECK(near(mesh.vertices[2].normal, {0, 1, 0}));
    CHECK(near(mesh.vertices[3].normal, {1, 0, 0}));
    CHECK(near(mesh.vertices[5].normal, {0, 1, 0}));  // unused: +Y, still unit length
    const std::string nonUnit = test::firstNonUnitNormal(mesh);
    INFO(nonUnit);
    CHECK(nonUnit.empty());
}

TEST_CASE("computeSmoothNormals gives a flat mesh its face normal", "[geometry][mesh]") {
    Mesh mesh = unitSquare();
    for (Vertex& v : mesh.vertices) v.normal = {0, 0, 0};
    computeSmoothNormals(mesh);
    for (const Vertex& v : mesh.vertices) CHECK(near(v.normal, {0, 0, 1}));
    const std::string againstNormals = test::firstTriangleAgainstNormals(mesh);
    INFO(againstNormals);
    CHECK(againstNormals.empty());
}
