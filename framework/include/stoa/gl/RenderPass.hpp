#pragma once
// The start of a pass, stated whole (after sokol's sg_begin_pass): which
// target, which part of it, what to clear, and the RenderState to draw with.
// Nothing of the pass before carries over, so passes give the same pictures in
// any order.
//
//   PassDescription pass;
//   pass.target = &shadowMap;         // the whole map is the viewport
//   pass.clear.depth = true;
//   pass.state.cull = CullMode::None; // both faces
//   beginPass(pass);
//   ...draw...

#include <stoa/gl/RenderState.hpp>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace stoa {

class Framebuffer;

/// What beginPass() clears before the pass draws. Clears write whatever the
/// pass's masks say (a pass with depth.write = false still clears depth).
struct PassClear {
    bool color = false;
    glm::vec4 colorValue{0.0f, 0.0f, 0.0f, 1.0f};
    bool depth = false;
    float depthValue = 1.0f;
    bool stencil = false;
    int stencilValue = 0;
};

struct PassDescription {
    /// The framebuffer drawn into; nullptr: the one bound now (the app's
    /// target: the window, or the headless frame a case is rendered into).
    const Framebuffer* target = nullptr;
    RenderState state;
    PassClear clear;
    /// x, y (from the bottom-left corner), width, height in pixels. Width 0:
    /// the whole target, which then must not be nullptr.
    glm::ivec4 viewport{0};
};

/// Binds the target (only if it is not bound), sets the viewport, applies the
/// state and clears what `pass.clear` asks for.
void beginPass(const PassDescription& pass);

/// A pass into the framebuffer bound now, over `size` pixels from the corner.
PassDescription passInto(glm::ivec2 size, const RenderState& state = {});
/// A pass into all of `target`; nothing cleared.
PassDescription passInto(const Framebuffer& target, const RenderState& state = {});

} // namespace stoa
