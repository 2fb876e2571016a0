// Lab 03: facet and smooth vertex normals. Read docs/labs/03_meshes.md first.
// The declarations, with what each function must return, are in lab03.hpp
// (next to this file), which this file and the app include. Use glm::cross, glm::dot,
// glm::normalize, glm::length and std::acos; stoa::computeSmoothNormals is the
// area-weighted version you are not to call.

#include "lab03.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace stoa {

Mesh facetNormals(const Mesh& mesh) {
    Mesh facets;
    facets.vertices.reserve(mesh.indices.size());
    facets.indices.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[t]];
        const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        const glm::vec3 cross = glm::cross(b.position - a.position, c.position - a.position);
        const float length = glm::length(cross);
        const glm::vec3 normal = length > 0.0f ? cross / length : glm::vec3(0.0f, 1.0f, 0.0f);
        for (const Vertex* corner : {&a, &b, &c}) {
            Vertex vertex = *corner;
            vertex.normal = normal;
            facets.indices.push_back(static_cast<std::uint32_t>(facets.vertices.size()));
            facets.vertices.push_back(vertex);
        }
    }
    return facets;
}

void smoothNormals(Mesh& mesh) {
    std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t corners[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        const glm::vec3 p[3] = {mesh.vertices[corners[0]].position, mesh.vertices[corners[1]].position,
                                mesh.vertices[corners[2]].position};
        const glm::vec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float area2 = glm::length(cross);
        if (!(area2 > 0.0f)) continue;
        const glm::vec3 faceNormal = cross / area2;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 toNext = p[(k + 1) % 3] - p[k];
            const glm::vec3 toPrevious = p[(k + 2) % 3] - p[k];
            const float lengths = glm::length(toNext) * glm::length(toPrevious);
            if (!(lengths > 0.0f)) continue;
            // The angle at corner k; clamped, as rounding can push the cosine past 1.
            const float angle = std::acos(glm::clamp(glm::dot(toNext, toPrevious) / lengths, -1.0f, 1.0f));
            sums[corners[k]] += angle * faceNormal;
        }
    }
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const float length = glm::length(sums[i]);
        mesh.vertices[i].normal = length > 0.0f ? sums[i] / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

} // namespace stoa
