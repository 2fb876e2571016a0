#pragma once
// Draws a scene in one pass with one program: begins a pass into the bound
// framebuffer (clears it; `state` says how to draw), fills the per-frame
// uniform block (FrameUniforms: camera and lights, shaders/common/frame.glsl)
// once, builds the scene's DrawList, drops what the lab's visibility hook
// rejects, and draws each item with the per-object uniforms of ObjectUniforms
// (locations looked up once per program).

#include <stoa/gl/RenderState.hpp>
#include <stoa/scene/DrawList.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>

namespace stoa {

class Camera;
class FrameUniforms;
class ObjectUniforms;
class Program;
class Scene;

class ForwardRenderer {
public:
    ForwardRenderer();
    ~ForwardRenderer();
    ForwardRenderer(ForwardRenderer&&) noexcept;
    ForwardRenderer& operator=(ForwardRenderer&&) noexcept;

    glm::vec3 clearColor{0.05f, 0.06f, 0.08f};
    /// What the pass draws with; the default: depth test (less), back faces culled.
    RenderState state;
    /// Skip the items that the student's visibility test (StudentCode::culling.isVisible)
    /// rejects; it must then be handed over. Off: every item is drawn.
    bool cull = false;

    /// Renders into the framebuffer that is bound, over a viewport of `size`
    /// pixels. The GL objects (the uniform buffer) are made at the first call.
    void render(const Scene& scene, const Camera& camera, const Program& program, glm::ivec2 size) const;

    /// How many items the last render() drew, and how many culling dropped.
    std::size_t drawnCount() const { return m_drawn; }
    std::size_t culledCount() const { return m_culled; }

private:
    const ObjectUniforms& uniformsFor(const Program& program) const;

    // Made at the first render() (a renderer may be made before the context).
    mutable std::unique_ptr<FrameUniforms> m_frame;
    mutable std::unique_ptr<ObjectUniforms> m_uniforms;   // for m_uniformsProgram
    mutable const Program* m_uniformsProgram = nullptr;
    mutable unsigned m_uniformsProgramId = 0;              // the id it was looked up in (a reload makes a new one)
    mutable DrawList m_drawList;                           // reused from frame to frame
    mutable std::size_t m_drawn = 0;
    mutable std::size_t m_culled = 0;
};

} // namespace stoa
