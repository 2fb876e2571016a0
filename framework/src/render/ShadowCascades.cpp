#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/render/ShadowCascades.hpp>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <string>

namespace stoa {

// The bias (slope factor, minimum, maximum) in shadow-map texels of world size:
// the 1024^2 sun map of the single-map cases spends about 0.04 m per texel and
// uses kSunBias = (0.004, 0.001, 0.015) of a 40 m depth range, i.e. these.
static constexpr glm::vec3 kCascadeBiasTexels{4.0f, 1.0f, 15.0f};

// Its matrix is an orthographic projection times a rotation, so the length of
// row 0 is 2 / (box width) and that of row 2 is 2 / (depth range).
glm::vec3 cascadeDepthBias(const glm::mat4& matrix, int mapSize) {
    const float rowX = glm::length(glm::vec3(matrix[0][0], matrix[1][0], matrix[2][0]));
    const float rowZ = glm::length(glm::vec3(matrix[0][2], matrix[1][2], matrix[2][2]));
    const float texelWorld = 2.0f / (rowX * static_cast<float>(mapSize));
    const float depthRange = 2.0f / rowZ;
    return kCascadeBiasTexels * (texelWorld / depthRange);
}

void ShadowCascades::split(const Camera& camera, float far, int count, float lambda) {
    STOA_ASSERT(count >= 1 && count <= kMaxCascades, "ShadowCascades::split(): count must be 1 to 4");
    m_splits = studentCode().shadows.cascadeSplits(camera.nearPlane(), far, count, lambda);   // the student's
    STOA_ASSERT(m_splits.size() == static_cast<std::size_t>(count) + 1,
                "cascadeSplits(): must return count + 1 depths, near first and far last");
    m_count = count;
}

Framebuffer& ShadowCascades::fit(int i, const Camera& camera, float aspect, const glm::vec3& sunDirection, int mapSize,
                                 const glm::vec3& sceneMin, const glm::vec3& sceneMax) {
    const ShadowFunctions& code = studentCode().shadows;
    const auto cascade = static_cast<std::size_t>(i);
    const std::array<glm::vec3, 8> corners = code.frustumSliceCorners(camera.viewMatrix(), camera.fovYDegrees(), aspect,
                                                                      m_splits[cascade], m_splits[cascade + 1]);
    m_matrices[cascade] = code.cascadeLightMatrix(sunDirection, corners, mapSize, sceneMin, sceneMax);
    if (m_maps[cascade].width() != mapSize) {
        FramebufferOptions options;
        options.color = false;
        options.depthTexture = true;
        m_maps[cascade] = Framebuffer(mapSize, mapSize, options);
    }
    return m_maps[cascade];
}

void ShadowCascades::setUniforms(const Program& program, int firstUnit, int mapSize, float unsplitFar,
                                 bool bindMaps) const {
    glm::vec4 splitFar(unsplitFar);
    for (int i = 0; i < kMaxCascades; ++i) {
        const auto cascade = static_cast<std::size_t>(i);
        const std::string index = "[" + std::to_string(i) + "]";
        program.set("uCascadeMaps" + index, firstUnit + i);
        if (i >= m_count) continue;
        splitFar[i] = m_splits[cascade + 1];
        if (bindMaps) m_maps[cascade].bindDepthTexture(firstUnit + i);
        program.set("uCascadeMatrices" + index, m_matrices[cascade]);
        program.set("uCascadeBiases" + index, cascadeDepthBias(m_matrices[cascade], mapSize));
    }
    program.set("uCascadeSplits", splitFar);
}

} // namespace stoa
