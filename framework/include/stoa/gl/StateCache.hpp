#pragma once
// What the framework knows of the current context's GL state, so that it sets
// only what changes and never asks the driver (no glGet round trips in a pass).
//
// The rule: the wrappers bind through here (Program::use(), Framebuffer::bind(),
// beginPass()), each changing only the binding it is named for; a pass states
// its whole RenderState and the cache skips the calls that would change nothing.
// Code that calls GL directly behind the cache's back (a student's pass that
// calls glEnable) must be followed by forget(): the framework renderers do that
// after every call into lab code.
//
// One cache per context, in its GpuResources: current() is the current
// context's, reset when HeadlessContext or Window makes its context current.

#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/RenderState.hpp>

#include <cstddef>
#include <string>

namespace stoa {

class StateCache {
public:
    /// The cache of the current context.
    static StateCache& current();

    /// A context was just created and made current: GL's defaults (no program,
    /// framebuffer 0); the render state is unknown until the first apply().
    void reset();
    /// Something changed GL state behind the cache's back: every later call
    /// goes to GL once (the bound framebuffers are asked for again, once).
    void forget();

    /// Sets the parts of `state` that differ from the last state applied.
    void apply(const RenderState& state);
    /// glUseProgram(id) unless it is current already.
    void useProgram(GLuint id);
    /// The program in use (asks GL once after forget()).
    GLuint program();
    /// glBindFramebuffer for drawing and reading, unless both are `id` already.
    void bindFramebuffer(GLuint id);
    void bindReadFramebuffer(GLuint id);
    /// The framebuffer draws go to (asks GL once after forget()).
    GLuint drawFramebuffer();
    GLuint readFramebuffer();

    /// GL objects being deleted: a binding to them is gone (GL binds 0 for a
    /// deleted framebuffer; a deleted program that is in use stays in use).
    void programDeleted(GLuint id);
    void framebufferDeleted(GLuint id);

    /// Asks GL for the render state (depth, culling, blending, colour mask,
    /// stencil) and lists each part that differs from what the last apply()
    /// set, e.g. "GL_CULL_FACE is enabled (the pass said: off)"; empty when
    /// they agree or nothing has been applied since forget().
    std::string differencesFromGl() const;

    /// Calls made and calls skipped as redundant since the last reset(): for tests and benchmarks.
    std::size_t callsMade() const { return m_made; }
    std::size_t callsSkipped() const { return m_skipped; }

private:
    template <typename T, typename Set>
    void update(T& known, const T& wanted, Set set);

    RenderState m_state;
    bool m_stateKnown = false;
    GLuint m_program = 0;
    bool m_programKnown = false;
    GLuint m_drawFramebuffer = 0;
    GLuint m_readFramebuffer = 0;
    bool m_framebuffersKnown = false;
    std::size_t m_made = 0;
    std::size_t m_skipped = 0;
};

} // namespace stoa
