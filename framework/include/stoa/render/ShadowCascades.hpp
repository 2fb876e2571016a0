#pragma once
// Cascaded shadow maps for the sun (docs/labs/05_shadows.md, "Cascaded shadow
// maps"): the camera's frustum split in depth, each slice fitted a light matrix
// and given a depth map of its own. The splits and the fit are the student's
// (StudentCode::shadows: cascadeSplits(), frustumSliceCorners(),
// cascadeLightMatrix()); what the casters are and how they are drawn into each
// map is the caller's. Lab 05's ShadowRenderer and the CourseRenderer both
// shadow through it:
//
//   cascades.split(camera, far, count, lambda);
//   for (int i = 0; i < cascades.count(); ++i) {
//       Framebuffer& map = cascades.fit(i, camera, aspect, sun, mapSize, sceneMin, sceneMax);
//       ... draw the casters into map with cascades.matrix(i) ...
//   }
//   cascades.setUniforms(program, firstUnit, mapSize, far, true);

#include <stoa/gl/Framebuffer.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace stoa {

class Camera;
class Program;

/// A cascade's depth bias (slope factor, minimum, maximum) in its own window-depth
/// units, for shadows.glsl's slopeScaledBias(): a fixed number of its texels'
/// world size, so that every cascade's bias covers the same share of a texel.
glm::vec3 cascadeDepthBias(const glm::mat4& cascadeMatrix, int mapSize);

class ShadowCascades {
public:
    static constexpr int kMaxCascades = 4;   // MAX_CASCADES of shaders/shadows/cascaded.frag and course/sun.frag

    /// Splits the camera's view depth from its near plane to `far` into
    /// `count` slices (1..kMaxCascades) with the student's cascadeSplits().
    void split(const Camera& camera, float far, int count, float lambda);
    /// Fits slice `i` a light matrix (the student's frustumSliceCorners() and
    /// cascadeLightMatrix()) and makes its map `mapSize` texels square; returns
    /// the map, for the caller to draw the casters into with matrix(i).
    Framebuffer& fit(int i, const Camera& camera, float aspect, const glm::vec3& sunDirection, int mapSize,
                     const glm::vec3& sceneMin, const glm::vec3& sceneMax);
    /// No cascades: the sun casts no shadow this frame.
    void clear() { m_count = 0; }

    int count() const { return m_count; }
    const glm::mat4& matrix(int i) const { return m_matrices[static_cast<std::size_t>(i)]; }
    const Framebuffer& map(int i) const { return m_maps[static_cast<std::size_t>(i)]; }

    /// Sets the cascaded shaders' uniforms on `program` (in use): uCascadeMaps[i]
    /// for every one of kMaxCascades (units from `firstUnit`; a sampler needs
    /// one used or not), and for each cascade uCascadeMatrices[i] and
    /// uCascadeBiases[i]; uCascadeSplits, the slices' far depths (`unsplitFar`
    /// past the last). Binds the maps to their units when `bindMaps`.
    void setUniforms(const Program& program, int firstUnit, int mapSize, float unsplitFar, bool bindMaps) const;

private:
    int m_count = 0;
    std::vector<float> m_splits;   // count + 1 depths, near first
    std::array<Framebuffer, kMaxCascades> m_maps;
    std::array<glm::mat4, kMaxCascades> m_matrices{};
};

} // namespace stoa
