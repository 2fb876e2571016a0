// Lab 03's property checks; see checks.hpp. Real meshes have degenerate
// triangles (exporters leave slivers and repeated corners); the statue's
// pictures would not show one bad normal among thousands.

#include "checks.hpp"
#include "lab03.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <string>

namespace lab03 {

namespace {

bool near(const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-3f; }

// Vertices 0-2: a good triangle, tilted (face normal (0, 0.71, 0.71)); 3-5: three
// points on a line (zero area); 6-7: a triangle 6, 6, 7 (a zero-length edge);
// 8: used by no triangle. Triangle 0, 1, 1 gives vertices 0 and 1 a zero edge too.
stoa::Mesh degenerateMesh() {
    stoa::Mesh mesh;
    const glm::vec3 positions[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, -1}, {2, 0, 0}, {3, 0, 0},
                                   {4, 0, 0}, {5, 0, 0}, {6, 1, 0}, {7, 0, 0}};
    for (const glm::vec3& position : positions) {
        stoa::Vertex vertex{};
        vertex.position = position;
        vertex.normal = glm::vec3(0.0f, 0.0f, 1.0f);
        mesh.vertices.push_back(vertex);
    }
    mesh.indices = {0, 1, 2, 3, 4, 5, 6, 6, 7, 0, 1, 1};
    return mesh;
}

// The first problem with `normal`, or "" when it is the `expected` unit vector.
std::string problemWith(const glm::vec3& normal, const glm::vec3& expected) {
    if (!std::isfinite(normal.x) || !std::isfinite(normal.y) || !std::isfinite(normal.z))
        return "is not finite, " + stoa::checkVector(normal, 2);
    if (!near(normal, expected)) return "is " + stoa::checkVector(normal, 2) + ", expected " + stoa::checkVector(expected, 2);
    return "";
}

// Two triangles that share vertex 0 at the origin: a large one in the plane z = 0
// (normal +Z) whose angle there is 150 degrees, and a small one in the plane y = 0
// (normal +Y) whose angle there is 30 degrees. Edge lengths 4 and 0.5.
stoa::Mesh obtuseFan() {
    stoa::Mesh mesh;
    const float pi = glm::pi<float>();
    const glm::vec3 positions[] = {{0, 0, 0},
                                   {4, 0, 0},
                                   {4.0f * std::cos(5.0f * pi / 6.0f), 4.0f * std::sin(5.0f * pi / 6.0f), 0},
                                   {0, 0, 0.5f},
                                   {0.5f * std::sin(pi / 6.0f), 0, 0.5f * std::cos(pi / 6.0f)}};
    for (const glm::vec3& position : positions) {
        stoa::Vertex vertex{};
        vertex.position = position;
        mesh.vertices.push_back(vertex);
    }
    mesh.indices = {0, 1, 2, 0, 3, 4};
    return mesh;
}

} // namespace

stoa::CheckResult checkAngleWeights() {
    stoa::Mesh fan = obtuseFan();
    stoa::smoothNormals(fan);
    // 150 degrees of +Z and 30 of +Y: (0, 1, 5) / |(0, 1, 5)|, whatever the triangles' sizes.
    const glm::vec3 expected = glm::normalize(glm::vec3(0.0f, 1.0f, 5.0f));
    const glm::vec3 got = fan.vertices[0].normal;
    const std::string what = "smoothNormals() at a vertex shared by a large triangle with a 150 degree corner there "
                             "(normal +Z) and a small one with a 30 degree corner (normal +Y): the normal ";
    if (const std::string problem = problemWith(got, expected); !problem.empty()) {
        if (near(got, glm::normalize(glm::vec3(0.0f, 1.0f, 4.0f))) || near(got, glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f))))
            return stoa::CheckResult::fail(what + problem + ": the 150 degree corner counts as " +
                                           (near(got, glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f))) ? "30" : "120") +
                                           " degrees; an obtuse angle needs acos of the whole cosine, from -1 to 1 "
                                           "(docs: Smooth normals)");
        return stoa::CheckResult::fail(what + problem + ": each unit face normal counts by its angle at the vertex, "
                                                        "150 and 30 degrees, not by the triangle's size (docs: Smooth normals)");
    }
    return stoa::CheckResult::pass("an obtuse corner counts with its whole angle, and a triangle's size does not count");
}

stoa::CheckResult checkDegenerateTriangles() {
    const glm::vec3 up(0.0f, 1.0f, 0.0f), tilted = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f));

    const stoa::Mesh facets = stoa::facetNormals(degenerateMesh());
    const glm::vec3 facetExpected[] = {tilted, up, up, up};
    const char* const facetWhat[] = {"the good triangle", "the triangle of zero area", "the triangle with a zero edge",
                                     "the triangle 0, 1, 1"};
    if (facets.indices.size() != 12 || facets.vertices.size() != 12)
        return stoa::CheckResult::fail("facetNormals() of a mesh of 4 triangles returned " +
                                       std::to_string(facets.vertices.size()) + " vertices and " +
                                       std::to_string(facets.indices.size()) +
                                       " indices; expected 12 of each, 3 per triangle (docs: Facet normals)");
    for (int t = 0; t < 4; ++t)
        for (int k = 0; k < 3; ++k) {
            const std::string problem = problemWith(facets.vertices[facets.indices[3 * t + k]].normal, facetExpected[t]);
            if (!problem.empty())
                return stoa::CheckResult::fail(std::string("facetNormals(): the normal of ") + facetWhat[t] + " " + problem +
                                               "; a triangle of zero area gets +Y (docs: Facet normals)");
        }

    stoa::Mesh smooth = degenerateMesh();
    stoa::smoothNormals(smooth);
    const char* const what[] = {"vertex 0 (the good triangle, and a zero edge)", "vertex 1 (the good triangle, and a zero edge)",
                                "vertex 2 (the good triangle)", "vertex 3 (zero area only)", "vertex 4 (zero area only)",
                                "vertex 5 (zero area only)", "vertex 6 (a zero edge only)", "vertex 7 (a zero edge only)",
                                "vertex 8 (no triangle)"};
    for (std::size_t i = 0; i < smooth.vertices.size() && i < 9; ++i) {
        const glm::vec3 expected = i < 3 ? tilted : up;
        const std::string problem = problemWith(smooth.vertices[i].normal, expected);
        if (!problem.empty())
            return stoa::CheckResult::fail(std::string("smoothNormals(): the normal of ") + what[i] + " " + problem +
                                           ": a degenerate triangle adds nothing, and a vertex that gets nothing is +Y "
                                           "(docs: Smooth normals)");
    }
    // A sliver, not degenerate (area 6e-6): in floats the cosine at its corner 1
    // comes out as 1.00000012 and at corner 2 as -1.00000012, past [-1, 1], where
    // acos is NaN. Corner 1 also has a right-angled triangle of normal +Z.
    stoa::Mesh sliver;
    const glm::vec3 a(-0.740419149f, -0.198111236f, -0.686641812f), b(-0.563486218f, 0.997848988f, -0.782382369f),
        c(-0.65057981f, 0.409178942f, -0.735255003f);
    for (const glm::vec3& p : {a, b, c, b + glm::vec3(1.0f, 0.0f, 0.0f), b + glm::vec3(0.0f, 1.0f, 0.0f)}) {
        stoa::Vertex vertex;
        vertex.position = p;
        sliver.vertices.push_back(vertex);
    }
    sliver.indices = {0, 1, 2, 1, 3, 4};
    stoa::smoothNormals(sliver);
    const glm::vec3 atB = sliver.vertices[1].normal, atC = sliver.vertices[2].normal;
    const bool unitAtC = std::fabs(glm::length(atC) - 1.0f) < 1e-3f;
    if (!(glm::length(atB - glm::vec3(0.0f, 0.0f, 1.0f)) < 1e-3f) || !unitAtC ||
        !(std::fabs(glm::dot(atC, b - a)) < 1e-3f && std::fabs(glm::dot(atC, c - a)) < 1e-3f))
        return stoa::CheckResult::fail("smoothNormals() of a sliver triangle, whose corners' cosines round to just past "
                                       "1 and -1 in floats, gave its nearly 0-degree corner, shared with a right "
                                       "angle of normal +Z, the normal " + stoa::checkVector(atB) +
                                       " (expected +Z), and its nearly 180-degree corner, in no other triangle, " +
                                       stoa::checkVector(atC) + " (expected the sliver's own normal). Clamp the "
                                       "cosine to [-1, 1] before acos, which is NaN past it (docs: Smooth normals)");
    return stoa::CheckResult::pass("degenerate triangles add nothing, and what gets nothing is +Y, in both functions; "
                                   "a sliver's cosines past [-1, 1] are clamped");
}

} // namespace lab03
