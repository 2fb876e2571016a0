// Lab 04, part 1: a tangent frame at every vertex.
// Read docs/labs/04_normal_mapping.md, "The tangent frame", first.
// The normal map stores normals in a frame that follows the texture: x along
// the direction in which u grows (the tangent T), y along the direction in
// which v grows (the bitangent B), z along the surface normal N. The vertex
// shader needs T and the sign of B for every vertex; this file computes them.

#include "lab04.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace stoa {

namespace {

// Any unit vector perpendicular to the unit vector n: cross n with the axis it
// is least aligned with, so the cross product cannot vanish.
glm::vec3 anyPerpendicular(const glm::vec3& n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(axis, n));
}

} // namespace

void computeTangents(Mesh& mesh) {
    std::vector<glm::vec3> tangentSums(mesh.vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bitangentSums(mesh.vertices.size(), glm::vec3(0.0f));

    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        const Vertex& v0 = mesh.vertices[i0];
        const glm::vec3 edge1 = mesh.vertices[i1].position - v0.position;
        const glm::vec3 edge2 = mesh.vertices[i2].position - v0.position;
        const glm::vec2 duv1 = mesh.vertices[i1].uv - v0.uv;
        const glm::vec2 duv2 = mesh.vertices[i2].uv - v0.uv;

        // edge1 = duv1.x T + duv1.y B and edge2 = duv2.x T + duv2.y B: a 2x2
        // system whose inverse has 1/det in front (Cramer's rule).
        const float det = duv1.x * duv2.y - duv2.x * duv1.y;
        if (std::abs(det) < 1e-12f) continue;  // uvs on a line: no direction to learn
        const float r = 1.0f / det;
        const glm::vec3 tangent = (edge1 * duv2.y - edge2 * duv1.y) * r;
        const glm::vec3 bitangent = (edge2 * duv1.x - edge1 * duv2.x) * r;
        for (std::uint32_t i : {i0, i1, i2}) {
            tangentSums[i] += tangent;
            bitangentSums[i] += bitangent;
        }
    }

    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        Vertex& vertex = mesh.vertices[i];
        const glm::vec3 n = vertex.normal;
        // Gram-Schmidt: drop the part of T along N, so (T, B, N) is orthonormal.
        const glm::vec3 inPlane = tangentSums[i] - n * glm::dot(n, tangentSums[i]);
        const float length = glm::length(inPlane);
        if (!(length > 1e-8f) || !std::isfinite(length)) {
            vertex.tangent = glm::vec4(anyPerpendicular(n), 1.0f);
            continue;
        }
        const glm::vec3 tangent = inPlane / length;
        const float handedness = glm::dot(glm::cross(n, tangent), bitangentSums[i]) < 0.0f ? -1.0f : 1.0f;
        vertex.tangent = glm::vec4(tangent, handedness);
    }
}

} // namespace stoa
