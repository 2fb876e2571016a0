// The tangent on stoa::Vertex (lab 04): its layout, its default, and
// Mesh::validate() rejecting a tangent that is not finite.

#include "catch.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <cstddef>
#include <limits>
#include <string>

using stoa::InputError;
using stoa::Mesh;
using stoa::Vertex;

TEST_CASE("Vertex: the tangent follows the uv, 12 floats in all, and starts at zero") {
    // GpuMesh uploads Vertex as it is: attribute 3 (vec4) starts right after the uv.
    CHECK(offsetof(Vertex, tangent) == 8 * sizeof(float));
    CHECK(sizeof(Vertex) == 12 * sizeof(float));
    const Vertex vertex{{1, 2, 3}, {0, 0, 1}, {0.5f, 0.5f}};
    CHECK(vertex.tangent == glm::vec4(0.0f));
}

TEST_CASE("Mesh::validate rejects a tangent that is not finite, naming the source and the vertex") {
    Mesh mesh;
    mesh.vertices = {{{0, 0, 0}, {0, 0, 1}, {0, 0}}, {{1, 0, 0}, {0, 0, 1}, {1, 0}}, {{0, 1, 0}, {0, 0, 1}, {0, 1}}};
    mesh.indices = {0, 1, 2};
    mesh.vertices[1].tangent = {1, 0, 0, 1};
    CHECK_NOTHROW(mesh.validate("wall.obj"));

    mesh.vertices[2].tangent = {std::numeric_limits<float>::quiet_NaN(), 0, 0, 1};
    try {
        mesh.validate("wall.obj");
        FAIL("validate() accepted a NaN tangent");
    } catch (const InputError& error) {
        CHECK(error.file() == "wall.obj");
        CHECK(error.line() == 0);
        CHECK(error.message().find("vertex 2") != std::string::npos);
        CHECK(error.message().find("tangent") != std::string::npos);
    }
}
