#include <stoa/geometry/LevelOfDetail.hpp>

#include <stoa/core/Assert.hpp>

#include <meshoptimizer.h>

#include <algorithm>
#include <cstdint>

namespace stoa {

namespace {

// The vertices `indices` uses, in first-use order, and the indices renumbered to them.
Mesh compacted(const Mesh& source, std::vector<std::uint32_t> indices) {
    Mesh mesh;
    std::vector<std::uint32_t> remap(source.vertices.size(), UINT32_MAX);
    mesh.indices.reserve(indices.size());
    for (std::uint32_t index : indices) {
        if (remap[index] == UINT32_MAX) {
            remap[index] = static_cast<std::uint32_t>(mesh.vertices.size());
            mesh.vertices.push_back(source.vertices[index]);
        }
        mesh.indices.push_back(remap[index]);
    }
    return mesh;
}

} // namespace

std::vector<LodLevel> buildLevelsOfDetail(const Mesh& mesh, const std::vector<float>& triangleRatios,
                                          float maxRelativeError) {
    STOA_ASSERT(!mesh.vertices.empty() && !mesh.indices.empty(), "buildLevelsOfDetail() needs a mesh with triangles");
    for (std::size_t i = 0; i < triangleRatios.size(); ++i) {
        STOA_ASSERT(triangleRatios[i] > 0.0f && triangleRatios[i] <= 1.0f,
                    "buildLevelsOfDetail(): every triangle ratio must be in (0, 1]");
        STOA_ASSERT(i == 0 || triangleRatios[i] <= triangleRatios[i - 1],
                    "buildLevelsOfDetail(): triangle ratios must not increase from one level to the next");
    }
    const float* positions = &mesh.vertices[0].position.x;
    // Positions only: vertices repeated for another uv or normal count as one,
    // so that seams do not hold the simplifier back.
    std::vector<std::uint32_t> welded(mesh.indices.size());
    meshopt_generateShadowIndexBuffer(welded.data(), mesh.indices.data(), mesh.indices.size(), positions,
                                      mesh.vertices.size(), sizeof(glm::vec3), sizeof(Vertex));

    std::vector<LodLevel> levels;
    std::vector<std::uint32_t> previous = mesh.indices;
    for (float ratio : triangleRatios) {
        LodLevel level;
        level.triangleRatio = ratio;
        if (ratio >= 1.0f) {
            level.mesh = mesh;
        } else {
            const std::size_t target = std::max<std::size_t>(3, static_cast<std::size_t>(
                                                                    static_cast<double>(mesh.indices.size()) * ratio) /
                                                                    3 * 3);
            std::vector<std::uint32_t> simplified(welded.size());
            float error = 0.0f;
            const std::size_t count =
                meshopt_simplify(simplified.data(), welded.data(), welded.size(), positions, mesh.vertices.size(),
                                 sizeof(Vertex), target, maxRelativeError, 0, &error);
            simplified.resize(count);
            // Never more than the level before (a tighter error can stop earlier).
            if (count == 0 || count > previous.size()) simplified = previous;
            else level.relativeError = error;
            level.mesh = compacted(mesh, simplified);
            previous = std::move(simplified);
        }
        levels.push_back(std::move(level));
    }
    return levels;
}

} // namespace stoa
