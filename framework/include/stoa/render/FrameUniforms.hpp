#pragma once
// The per-frame uniforms (camera and lights) in one uniform buffer, filled and
// bound once per frame, that every framework shader reads through the block
// `Frame` of shaders/common/frame.glsl. FrameBlock mirrors that block in the
// std140 layout (the tests compare every offset with what GL reports).
//
//   FrameUniforms frame;                           // needs a current context
//   frame.update(camera, aspect, scene);           // once per frame
//   frame.bind();                                  // binding point kBinding
//   program.bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);   // once per program

#include <stoa/gl/Buffer.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace stoa {

class Camera;

/// The block `Frame`, byte for byte (std140: vec3s padded to 16 bytes,
/// array elements and structs aligned to 16).
struct FrameBlock {
    struct Directional {
        glm::vec3 direction;
        float padding0;
        glm::vec3 color;
        float padding1;
    };
    struct Point {
        glm::vec3 position;
        float padding0;
        glm::vec3 color;
        float padding1;
        glm::vec3 attenuation;
        float padding2;
    };
    glm::mat4 view;                        // offset 0
    glm::mat4 projection;                  // 64
    glm::vec3 cameraPosition;              // 128
    float padding0;
    glm::vec3 ambient;                     // 144
    std::int32_t directionalLightCount;    // 156
    std::int32_t pointLightCount;          // 160
    std::int32_t padding1[3];
    Directional directionalLights[Scene::kMaxDirectionalLights];   // 176
    Point pointLights[Scene::kMaxPointLights];                     // 304
};
static_assert(sizeof(FrameBlock) == 688, "FrameBlock must match shaders/common/frame.glsl's std140 layout");

class FrameUniforms {
public:
    static constexpr GLuint kBinding = 0;            // the uniform buffer binding point of `Frame`
    static constexpr const char* kBlockName = "Frame";

    /// Creates the buffer. Needs a current context.
    FrameUniforms();

    /// The block for `camera` (its projection at `aspect` = width / height)
    /// and the scene's ambient light and lights (those beyond the shaders'
    /// maxima are left out). No GL call.
    static FrameBlock blockFor(const Camera& camera, float aspect, const Scene& scene);
    /// Uploads `block`.
    void update(const FrameBlock& block);
    void update(const Camera& camera, float aspect, const Scene& scene) { update(blockFor(camera, aspect, scene)); }
    /// Binds the buffer to kBinding.
    void bind() const;

    const FrameBlock& block() const { return m_block; }

private:
    Buffer m_buffer{GL_UNIFORM_BUFFER};
    FrameBlock m_block{};
};

} // namespace stoa
