#pragma once
// The fixed-function state a pass draws with, stated whole: depth, culling,
// blending, colour mask, stencil. A pass fills one RenderState and hands it to
// beginPass() (RenderPass.hpp) or StateCache::apply(); every field it leaves
// alone has the default below, so a pass never inherits what the pass before
// it left on.
//
//   RenderState state;                 // opaque geometry: depth test (less), back faces culled
//   state.cull = CullMode::None;       // a shadow map: both faces
//
// The defaults are what the forward renderer of labs 01-05 draws with.

#include <stoa/gl/OpenGL.hpp>

#include <cstdint>

namespace stoa {

enum class CullMode { None, Back, Front };

/// How a fragment's colour combines with what is in the target.
enum class BlendMode {
    Opaque,        // no blending: the fragment replaces the target
    Alpha,         // src * a + dst * (1 - a): transparent surfaces, UI
    Additive,      // src + dst: light accumulation (deferred lights, particles)
    Premultiplied  // src + dst * (1 - a)
};

struct DepthState {
    bool test = true;          // false: every fragment passes (overlays, full-screen passes)
    GLenum func = GL_LESS;     // GL_LESS, GL_LEQUAL, GL_EQUAL, GL_ALWAYS, ...
    bool write = true;         // false: test against depth without changing it (transparent surfaces)
    bool operator==(const DepthState& other) const {
        return test == other.test && func == other.func && write == other.write;
    }
};

/// The same stencil test and operations for front and back faces.
struct StencilState {
    bool test = false;
    GLenum func = GL_ALWAYS;          // compares (ref & readMask) with (stored & readMask)
    int ref = 0;
    std::uint32_t readMask = 0xFF;
    GLenum stencilFail = GL_KEEP;     // the stencil test fails
    GLenum depthFail = GL_KEEP;       // the stencil test passes, the depth test fails
    GLenum pass = GL_KEEP;            // both pass
    std::uint32_t writeMask = 0xFF;
    bool operator==(const StencilState& other) const {
        return test == other.test && func == other.func && ref == other.ref && readMask == other.readMask &&
               stencilFail == other.stencilFail && depthFail == other.depthFail && pass == other.pass &&
               writeMask == other.writeMask;
    }
};

/// Which colour channels a draw writes.
struct ColorMask {
    bool red = true, green = true, blue = true, alpha = true;
    bool operator==(const ColorMask& other) const {
        return red == other.red && green == other.green && blue == other.blue && alpha == other.alpha;
    }
};

struct RenderState {
    DepthState depth;
    CullMode cull = CullMode::Back;    // counter-clockwise triangles are front faces
    BlendMode blend = BlendMode::Opaque;
    ColorMask colorMask;
    StencilState stencil;

    /// Depth test off, nothing culled: full-screen passes and overlays.
    static RenderState overlay() {
        RenderState state;
        state.depth.test = false;
        state.depth.write = false;
        state.cull = CullMode::None;
        return state;
    }

    bool operator==(const RenderState& other) const {
        return depth == other.depth && cull == other.cull && blend == other.blend && colorMask == other.colorMask &&
               stencil == other.stencil;
    }
    bool operator!=(const RenderState& other) const { return !(*this == other); }
};

} // namespace stoa
