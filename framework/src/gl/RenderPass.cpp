#include <stoa/gl/RenderPass.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/StateCache.hpp>

namespace stoa {

void beginPass(const PassDescription& pass) {
    STOA_ASSERT(pass.viewport.z > 0 || pass.target != nullptr,
                "beginPass(): a pass into the bound framebuffer needs its viewport (width and height in pixels); "
                "name the target or use passInto(size)");
    StateCache& cache = StateCache::current();
    if (pass.target) pass.target->bind();
    const glm::ivec4 viewport =
        pass.viewport.z > 0 ? pass.viewport : glm::ivec4(0, 0, pass.target->width(), pass.target->height());
    STOA_ASSERT(viewport.z > 0 && viewport.w > 0, "beginPass(): the viewport must not be empty");
    STOA_GL_CALL(glViewport(viewport.x, viewport.y, viewport.z, viewport.w));

    const PassClear& clear = pass.clear;
    if (clear.color || clear.depth || clear.stencil) {
        // glClear obeys the write masks: open those of what is cleared first.
        RenderState clearing = pass.state;
        GLbitfield bits = 0;
        if (clear.color) {
            clearing.colorMask = ColorMask{};
            STOA_GL_CALL(glClearColor(clear.colorValue.r, clear.colorValue.g, clear.colorValue.b, clear.colorValue.a));
            bits |= GL_COLOR_BUFFER_BIT;
        }
        if (clear.depth) {
            clearing.depth.write = true;
            STOA_GL_CALL(glClearDepth(clear.depthValue));
            bits |= GL_DEPTH_BUFFER_BIT;
        }
        if (clear.stencil) {
            clearing.stencil.writeMask = 0xFF;
            STOA_GL_CALL(glClearStencil(clear.stencilValue));
            bits |= GL_STENCIL_BUFFER_BIT;
        }
        cache.apply(clearing);
        STOA_GL_CALL(glClear(bits));
    }
    cache.apply(pass.state);
}

PassDescription passInto(glm::ivec2 size, const RenderState& state) {
    PassDescription pass;
    pass.state = state;
    pass.viewport = {0, 0, size.x, size.y};
    return pass;
}

PassDescription passInto(const Framebuffer& target, const RenderState& state) {
    PassDescription pass;
    pass.target = &target;
    pass.state = state;
    return pass;
}

} // namespace stoa
