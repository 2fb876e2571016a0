// Lab 03's facet and smooth normals against independent computations: face
// normals from the plane equation of three points, corner angles from the law
// of cosines on edge lengths (the solution uses dot products), and the
// property that makes angle weighting worth it: splitting a triangle does not
// change the normals.

#include "catch.hpp"

#include "lab03.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using stoa::Mesh;
using stoa::Vertex;

namespace {

bool near(const glm::vec3& a, const glm::vec3& b, float epsilon = 1e-4f) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(epsilon)));
}

Vertex vertexAt(glm::vec3 position, glm::vec2 uv = glm::vec2(0.0f)) {
    Vertex vertex;
    vertex.position = position;
    vertex.uv = uv;
    return vertex;
}

/// A bumpy height field of (n+1)^2 vertices and 2n^2 triangles, counter-clockwise seen from +Y,
/// with random jitter so that triangles differ in shape and size.
Mesh bumpyGrid(int n, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
    Mesh mesh;
    for (int z = 0; z <= n; ++z)
        for (int x = 0; x <= n; ++x) {
            const glm::vec3 p(x + jitter(random), 0.5f * std::sin(0.7f * x) * std::cos(0.9f * z) + jitter(random),
                              z + jitter(random));
            mesh.vertices.push_back(vertexAt(p, {float(x) / n, float(z) / n}));
        }
    for (int z = 0; z < n; ++z)
        for (int x = 0; x < n; ++x) {
            const std::uint32_t a = z * (n + 1) + x, b = a + 1, c = a + (n + 1), d = c + 1;
            // Seen from +Y (looking down -Y), a -> c -> b runs counter-clockwise.
            for (std::uint32_t i : {a, c, b, b, c, d}) mesh.indices.push_back(i);
        }
    return mesh;
}

/// The unit normal of the plane through p, q, r (in that counter-clockwise
/// order) from the coefficients of its equation ax + by + cz = d, each a 2x2
/// determinant of the coordinates (Cramer), not a cross-product call.
glm::vec3 planeNormal(glm::vec3 p, glm::vec3 q, glm::vec3 r) {
    const float a = (q.y - p.y) * (r.z - p.z) - (r.y - p.y) * (q.z - p.z);
    const float b = (q.z - p.z) * (r.x - p.x) - (r.z - p.z) * (q.x - p.x);
    const float c = (q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y);
    return glm::vec3(a, b, c) / std::sqrt(a * a + b * b + c * c);
}

/// The angle at corner p of triangle p, q, r from its side lengths (law of cosines).
float cornerAngle(glm::vec3 p, glm::vec3 q, glm::vec3 r) {
    const double a = glm::distance(q, r), b = glm::distance(p, q), c = glm::distance(p, r);
    return static_cast<float>(std::acos(std::clamp((b * b + c * c - a * a) / (2.0 * b * c), -1.0, 1.0)));
}

/// Angle-weighted vertex normals, computed with the helpers above.
std::vector<glm::vec3> referenceSmoothNormals(const Mesh& mesh) {
    std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const std::uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        const glm::vec3 p[3] = {mesh.vertices[i[0]].position, mesh.vertices[i[1]].position,
                                mesh.vertices[i[2]].position};
        const glm::vec3 normal = planeNormal(p[0], p[1], p[2]);
        for (int k = 0; k < 3; ++k) sums[i[k]] += cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]) * normal;
    }
    for (glm::vec3& sum : sums) sum = glm::normalize(sum);
    return sums;
}

} // namespace

TEST_CASE("facetNormals gives every triangle its own vertices with the face normal", "[labs][lab03]") {
    const Mesh mesh = bumpyGrid(6, 1);
    const Mesh facets = stoa::facetNormals(mesh);
    REQUIRE(facets.indices.size() == mesh.indices.size());
    REQUIRE(facets.vertices.size() == mesh.indices.size());
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 expected =
            planeNormal(mesh.vertices[mesh.indices[t]].position, mesh.vertices[mesh.indices[t + 1]].position,
                        mesh.vertices[mesh.indices[t + 2]].position);
        CHECK(expected.y > 0.0f);  // the grid faces +Y: the winding is kept
        for (std::size_t k = 0; k < 3; ++k) {
            INFO("triangle " << t / 3 << ", corner " << k);
            REQUIRE(facets.indices[t + k] == t + k);
            const Vertex& original = mesh.vertices[mesh.indices[t + k]];
            const Vertex& flat = facets.vertices[t + k];
            CHECK(near(flat.position, original.position, 0.0f));
            CHECK(flat.uv == original.uv);
            CHECK(near(flat.normal, expected));
        }
    }
}

TEST_CASE("facetNormals gives a triangle of zero area the normal +Y", "[labs][lab03]") {
    Mesh mesh;
    mesh.vertices = {vertexAt({0, 0, 0}), vertexAt({1, 1, 1}), vertexAt({2, 2, 2})};
    mesh.indices = {0, 1, 2};
    const Mesh facets = stoa::facetNormals(mesh);
    REQUIRE(facets.vertices.size() == 3);
    for (const Vertex& vertex : facets.vertices) CHECK(near(vertex.normal, {0, 1, 0}));
}

TEST_CASE("smoothNormals weights face normals by the corner angle", "[labs][lab03]") {
    for (unsigned seed : {2u, 3u, 4u}) {
        Mesh mesh = bumpyGrid(7, seed);
        const std::vector<glm::vec3> expected = referenceSmoothNormals(mesh);
        stoa::smoothNormals(mesh);
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            INFO("seed " << seed << ", vertex " << i);
            CHECK(near(mesh.vertices[i].normal, expected[i]));
            CHECK(std::abs(glm::length(mesh.vertices[i].normal) - 1.0f) < 1e-5f);
        }
    }
}

TEST_CASE("smoothNormals at a cube corner is the diagonal however the faces are cut", "[labs][lab03]") {
    // Three faces meet at the origin, the planes x = 0, y = 0 and z = 0, with
    // normals +x, +y and +z. The z = 0 face is cut into four triangles at the
    // corner, the others are one each: counting triangles (or areas) would tilt
    // the normal, angle weighting gives each face its 90 degrees.
    Mesh mesh;
    mesh.vertices = {vertexAt({0, 0, 0}),                                       // 0: the corner
                     vertexAt({1, 0, 0}), vertexAt({0, 1, 0}), vertexAt({0, 0, 1}),  // 1, 2, 3: the axes
                     vertexAt({1, 0.3f, 0}), vertexAt({1, 1, 0}), vertexAt({0.3f, 1, 0})};
    mesh.indices = {0, 2, 3,                           // x = 0, normal +x
                    0, 3, 1,                           // y = 0, normal +y
                    0, 1, 4, 0, 4, 5, 0, 5, 6, 0, 6, 2};  // z = 0, normal +z, in four slices
    stoa::smoothNormals(mesh);
    CHECK(near(mesh.vertices[0].normal, glm::normalize(glm::vec3(1, 1, 1))));
}

TEST_CASE("smoothNormals does not change when a triangle is split", "[labs][lab03]") {
    Mesh mesh = bumpyGrid(5, 5);
    Mesh split = mesh;
    // Split the first triangle (a, b, c) at the midpoint m of b-c into (a, b, m) and (a, m, c).
    const std::uint32_t a = split.indices[0], b = split.indices[1], c = split.indices[2];
    const auto m = static_cast<std::uint32_t>(split.vertices.size());
    split.vertices.push_back(vertexAt(0.5f * (split.vertices[b].position + split.vertices[c].position)));
    split.indices[2] = m;
    for (std::uint32_t i : {a, m, c}) split.indices.push_back(i);
    stoa::smoothNormals(mesh);
    stoa::smoothNormals(split);
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        INFO("vertex " << i);
        CHECK(near(split.vertices[i].normal, mesh.vertices[i].normal));
    }
}

TEST_CASE("smoothNormals skips degenerate triangles and gives unused vertices +Y", "[labs][lab03]") {
    Mesh mesh;
    mesh.vertices = {vertexAt({0, 0, 0}), vertexAt({1, 0, 0}), vertexAt({0, 0, -1}),
                     vertexAt({2, 0, 0}),  // on the line of 0 and 1: the second triangle has no area
                     vertexAt({5, 5, 5})};  // used by no triangle
    mesh.indices = {0, 1, 2, 0, 1, 3};
    stoa::smoothNormals(mesh);
    for (int i : {0, 1, 2}) CHECK(near(mesh.vertices[i].normal, {0, 1, 0}));
    CHECK(near(mesh.vertices[3].normal, {0, 1, 0}));
    CHECK(near(mesh.vertices[4].normal, {0, 1, 0}));
    for (const Vertex& vertex : mesh.vertices) CHECK(std::isfinite(vertex.normal.x));
}
