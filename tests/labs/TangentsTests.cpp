// Lab 04's computeTangents() against meshes whose uv -> position map is known:
// positions are built as P(u, v) = origin + u * dPdu + v * dPdv, so the tangent
// must be the in-plane direction of dPdu and the handedness the side dPdv lies on.

#include "catch.hpp"
#include "lab04.hpp"

#include <stoa/geometry/Mesh.hpp>
#include <stoa/geometry/Shapes.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace {

bool near(const glm::vec3& a, const glm::vec3& b, float epsilon = 1e-4f) { return glm::length(a - b) <= epsilon; }

// A grid of (cells + 1)^2 vertices over uv in [0, 1]^2 placed by the affine map
// above; every vertex gets `normal` (which may face either side of the plane).
stoa::Mesh affineGrid(glm::vec3 origin, glm::vec3 dPdu, glm::vec3 dPdv, glm::vec3 normal, int cells = 3) {
    stoa::Mesh mesh;
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            stoa::Vertex vertex;
            vertex.uv = glm::vec2(i, j) / static_cast<float>(cells);
            vertex.position = origin + vertex.uv.x * dPdu + vertex.uv.y * dPdv;
            vertex.normal = normal;
            mesh.vertices.push_back(vertex);
        }
    }
    const auto at = [cells](int i, int j) { return static_cast<std::uint32_t>(j * (cells + 1) + i); };
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return mesh;
}

void checkFrame(const stoa::Vertex& vertex) {
    const glm::vec3 t(vertex.tangent);
    CHECK(std::abs(glm::length(t) - 1.0f) < 1e-4f);
    CHECK(std::abs(glm::dot(t, vertex.normal)) < 1e-4f);
    CHECK(std::abs(vertex.tangent.w) == 1.0f);
}

} // namespace

TEST_CASE("computeTangents: a quad with u along +X and v along +Y has T = +X, w = +1") {
    stoa::Mesh mesh = affineGrid({-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}, 1);
    stoa::computeTangents(mesh);
    for (const stoa::Vertex& vertex : mesh.vertices) {
        CHECK(near(glm::vec3(vertex.tangent), {1, 0, 0}));
        CHECK(vertex.tangent.w == 1.0f);
    }
}

TEST_CASE("computeTangents: T is the unit in-plane direction of dP/du for a skewed, scaled uv map") {
    const glm::vec3 dPdu(1.5f, 0.4f, -0.3f), dPdv(0.2f, 0.9f, 0.8f);  // not perpendicular, not unit
    const glm::vec3 normal = glm::normalize(glm::cross(dPdu, dPdv));
    stoa::Mesh mesh = affineGrid({0.3f, -0.2f, 1.0f}, dPdu, dPdv, normal);
    stoa::computeTangents(mesh);
    const glm::vec3 expected = glm::normalize(dPdu - normal * glm::dot(normal, dPdu));
    for (const stoa::Vertex& vertex : mesh.vertices) {
        checkFrame(vertex);
        CHECK(near(glm::vec3(vertex.tangent), expected));
        CHECK(vertex.tangent.w == 1.0f);
        // The bitangent w * cross(N, T) points the way v grows.
        CHECK(glm::dot(vertex.tangent.w * glm::cross(normal, glm::vec3(vertex.tangent)), dPdv) > 0.0f);
    }
}

TEST_CASE("computeTangents: mirrored uvs give w = -1, and T still points the way u grows") {
    // u runs right to left: dP/du = -X, while v still runs up and the normal faces +Z.
    stoa::Mesh mesh = affineGrid({1, -1, 0}, {-2, 0, 0}, {0, 2, 0}, {0, 0, 1});
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    stoa::computeTangents(mesh);
    for (const stoa::Vertex& vertex : mesh.vertices) {
        checkFrame(vertex);
        CHECK(near(glm::vec3(vertex.tangent), {-1, 0, 0}));
        CHECK(vertex.tangent.w == -1.0f);
        const glm::vec3 bitangent = vertex.tangent.w * glm::cross(vertex.normal, glm::vec3(vertex.tangent));
        CHECK(near(bitangent, {0, 1, 0}));
    }
}

TEST_CASE("computeTangents: a normal that is not the face normal still gets a perpendicular tangent") {
    // Smooth normals lean away from the face: Gram-Schmidt keeps T perpendicular to them.
    const glm::vec3 leaning = glm::normalize(glm::vec3(0.3f, -0.2f, 1.0f));
    stoa::Mesh mesh = affineGrid({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, leaning);
    stoa::computeTangents(mesh);
    const glm::vec3 expected = glm::normalize(glm::vec3(1, 0, 0) - leaning * leaning.x);
    for (const stoa::Vertex& vertex : mesh.vertices) {
        checkFrame(vertex);
        CHECK(near(glm::vec3(vertex.tangent), expected));
    }
}

TEST_CASE("computeTangents: a sphere's tangents run east, along increasing u, with w = +1") {
    stoa::Mesh mesh = stoa::shapes::sphere(0.5f, 24, 12);
    stoa::computeTangents(mesh);
    for (const stoa::Vertex& vertex : mesh.vertices) {
        checkFrame(vertex);
        const glm::vec3 p = vertex.position;
        if (std::abs(p.y) > 0.45f) continue;  // near the poles "east" is ill-defined
        // u goes counter-clockwise around +Y from +Z: the direction of growth is (z, 0, -x).
        const glm::vec3 east = glm::normalize(glm::vec3(p.z, 0.0f, -p.x));
        CHECK(glm::dot(glm::vec3(vertex.tangent), east) > 0.95f);
        CHECK(vertex.tangent.w == 1.0f);
    }
}

TEST_CASE("computeTangents: triangles with degenerate uvs still leave unit, perpendicular tangents") {
    stoa::Mesh mesh = affineGrid({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1);
    for (stoa::Vertex& vertex : mesh.vertices) vertex.uv = glm::vec2(0.25f);  // every uv the same
    stoa::computeTangents(mesh);
    for (const stoa::Vertex& vertex : mesh.vertices) {
        checkFrame(vertex);
        CHECK(std::isfinite(vertex.tangent.x));
        CHECK(vertex.tangent.w == 1.0f);
    }
}

TEST_CASE("computeTangents: a degenerate triangle does not spoil the tangent of a vertex it shares") {
    stoa::Mesh mesh = affineGrid({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1);
    // A sliver whose uvs lie on a line, sharing vertex 0 with the good triangles.
    stoa::Vertex extra = mesh.vertices[0];
    extra.position = {-0.5f, -0.5f, 0.0f};
    extra.uv = {0.0f, 0.0f};
    mesh.vertices.push_back(extra);
    mesh.indices.insert(mesh.indices.end(), {0u, static_cast<std::uint32_t>(mesh.vertices.size() - 1), 0u});
    stoa::computeTangents(mesh);
    CHECK(near(glm::vec3(mesh.vertices[0].tangent), {1, 0, 0}));
    CHECK(mesh.vertices[0].tangent.w == 1.0f);
}
