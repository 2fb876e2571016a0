#pragma once
// Checks shared by the geometry tests. Each returns a description of the
// first vertex or triangle that breaks the property, or "" when none does, so
// a test reads CHECK(problem.empty()) and prints the culprit when it fails.

#include <stoa/geometry/Mesh.hpp>

#include <glm/geometric.hpp>
#include <glm/gtx/string_cast.hpp>

#include <cmath>
#include <functional>
#include <string>

namespace stoa::test {

inline bool near(float a, float b, float tolerance = 1e-5f) { return std::abs(a - b) <= tolerance; }
inline bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    return glm::length(a - b) <= tolerance;
}
inline bool near(const glm::vec2& a, const glm::vec2& b, float tolerance = 1e-5f) {
    return glm::length(a - b) <= tolerance;
}

inline std::string vertexText(const Mesh& mesh, std::size_t i) {
    const Vertex& v = mesh.vertices[i];
    return "vertex " + std::to_string(i) + " position " + glm::to_string(v.position) + " normal " +
           glm::to_string(v.normal) + " uv " + glm::to_string(v.uv);
}

inline std::string firstNonUnitNormal(const Mesh& mesh) {
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        if (!near(glm::length(mesh.vertices[i].normal), 1.0f)) return vertexText(mesh, i);
    }
    return "";
}

inline std::string firstUvOutsideUnitSquare(const Mesh& mesh) {
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const glm::vec2 uv = mesh.vertices[i].uv;
        if (uv.x < 0.0f || uv.x > 1.0f || uv.y < 0.0f || uv.y > 1.0f) return vertexText(mesh, i);
    }
    return "";
}

/// `outward(position)` gives a vector that points out of the surface at that
/// position (for a sphere: the position itself); the normal must not point against it.
inline std::string firstInwardNormal(const Mesh& mesh, const std::function<glm::vec3(glm::vec3)>& outward) {
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Vertex& v = mesh.vertices[i];
        if (glm::dot(v.normal, outward(v.position)) < -1e-6f) return vertexText(mesh, i);
    }
    return "";
}

/// A triangle is counter-clockwise seen from the side its vertex normals point
/// to when its geometric normal (p1 - p0) x (p2 - p0) agrees with each of them.
/// Degenerate triangles (zero area) count as problems too.
inline std::string firstTriangleAgainstNormals(const Mesh& mesh) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[t]];
        const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        const glm::vec3 faceNormal = glm::cross(b.position - a.position, c.position - a.position);
        const bool degenerate = glm::length(faceNormal) < 1e-9f;
        if (degenerate || glm::dot(faceNormal, a.normal) <= 0.0f || glm::dot(faceNormal, b.normal) <= 0.0f ||
            glm::dot(faceNormal, c.normal) <= 0.0f) {
            return "triangle " + std::to_string(t / 3) + " (" + vertexText(mesh, mesh.indices[t]) + "; " +
                   vertexText(mesh, mesh.indices[t + 1]) + "; " + vertexText(mesh, mesh.indices[t + 2]) +
                   ") face normal " + glm::to_string(faceNormal);
        }
    }
    return "";
}

/// The volume a closed mesh encloses, by the divergence theorem: the sum over
/// triangles of the signed volumes of the tetrahedra (origin, p0, p1, p2).
/// Positive when the triangles are counter-clockwise seen from outside.
inline float signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
        const glm::vec3 b = mesh.vertices[mesh.indices[t + 1]].position;
        const glm::vec3 c = mesh.vertices[mesh.indices[t + 2]].position;
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return static_cast<float>(volume);
}

/// Total area of the triangles.
inline float surfaceArea(const Mesh& mesh) {
    double area = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position;
        const glm::vec3 b = mesh.vertices[mesh.indices[t + 1]].position;
        const glm::vec3 c = mesh.vertices[mesh.indices[t + 2]].position;
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return static_cast<float>(area);
}

} // namespace stoa::test
