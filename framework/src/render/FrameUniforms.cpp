#include <stoa/camera/Camera.hpp>
#include <stoa/render/FrameUniforms.hpp>

#include <algorithm>

namespace stoa {

FrameUniforms::FrameUniforms() { m_buffer.upload(nullptr, sizeof(FrameBlock), GL_DYNAMIC_DRAW); }

FrameBlock FrameUniforms::blockFor(const Camera& camera, float aspect, const Scene& scene) {
    FrameBlock block{};
    block.view = camera.viewMatrix();
    block.projection = camera.projectionMatrix(aspect);
    block.cameraPosition = camera.eyePosition();
    block.ambient = scene.ambient;
    const int directional = std::min(static_cast<int>(scene.directionalLights.size()), Scene::kMaxDirectionalLights);
    block.directionalLightCount = directional;
    for (int i = 0; i < directional; ++i) {
        block.directionalLights[i].direction = scene.directionalLights[static_cast<std::size_t>(i)].direction;
        block.directionalLights[i].color = scene.directionalLights[static_cast<std::size_t>(i)].color;
    }
    const int point = std::min(static_cast<int>(scene.pointLights.size()), Scene::kMaxPointLights);
    block.pointLightCount = point;
    for (int i = 0; i < point; ++i) {
        const PointLight& light = scene.pointLights[static_cast<std::size_t>(i)];
        block.pointLights[i].position = light.position;
        block.pointLights[i].color = light.color;
        block.pointLights[i].attenuation = light.attenuation;
    }
    return block;
}

void FrameUniforms::update(const FrameBlock& block) {
    m_block = block;
    m_buffer.update(0, &m_block, sizeof(FrameBlock));
}

void FrameUniforms::bind() const { m_buffer.bindBase(kBinding); }

} // namespace stoa
