#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/scene/ObjectUniforms.hpp>
#include <stoa/scene/Scene.hpp>

#include <algorithm>

namespace stoa {

ForwardRenderer::ForwardRenderer() = default;
ForwardRenderer::~ForwardRenderer() = default;
ForwardRenderer::ForwardRenderer(ForwardRenderer&&) noexcept = default;
ForwardRenderer& ForwardRenderer::operator=(ForwardRenderer&&) noexcept = default;

const ObjectUniforms& ForwardRenderer::uniformsFor(const Program& program) const {
    if (!m_uniforms || m_uniformsProgram != &program || m_uniformsProgramId != program.id()) {
        m_uniforms = std::make_unique<ObjectUniforms>(program);
        m_uniformsProgram = &program;
        m_uniformsProgramId = program.id();
        program.bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
    }
    return *m_uniforms;
}

void ForwardRenderer::render(const Scene& scene, const Camera& camera, const Program& program, glm::ivec2 size) const {
    STOA_ASSERT(size.x > 0 && size.y > 0, "ForwardRenderer::render(): the viewport must not be empty");
    PassDescription pass = passInto(size, state);
    pass.clear.color = pass.clear.depth = true;
    pass.clear.colorValue = glm::vec4(clearColor, 1.0f);
    beginPass(pass);

    program.use();
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    if (!m_frame) m_frame = std::make_unique<FrameUniforms>();
    FrameBlock block = FrameUniforms::blockFor(camera, aspect, scene);
    m_frame->update(block);
    m_frame->bind();
    const ObjectUniforms& uniforms = uniformsFor(program);

    m_drawList.clear();
    for (const auto& object : scene.objects()) object->addDraws(m_drawList);
    m_drawn = m_culled = 0;
    const glm::mat4 viewProjection = block.projection * block.view;
    for (const DrawItem& item : m_drawList) {
        if (cull) {
            const Bounds world = transformed(item.mesh->bounds(), item.model);
            if (!studentCode().culling.isVisible(world.sphere, viewProjection)) {
                ++m_culled;
                continue;
            }
        }
        uniforms.apply(item);
        item.mesh->draw();
        ++m_drawn;
    }
}

} // namespace stoa
