#include <stoa/gl/GpuResources.hpp>
#include <stoa/gl/StateCache.hpp>

#include <stoa/gl/Debug.hpp>

namespace stoa {

namespace {

void setEnabled(GLenum capability, bool on) {
    if (on)
        STOA_GL_CALL(glEnable(capability));
    else
        STOA_GL_CALL(glDisable(capability));
}

void applyCull(CullMode mode) {
    setEnabled(GL_CULL_FACE, mode != CullMode::None);
    if (mode != CullMode::None) STOA_GL_CALL(glCullFace(mode == CullMode::Back ? GL_BACK : GL_FRONT));
}

void applyBlend(BlendMode mode) {
    setEnabled(GL_BLEND, mode != BlendMode::Opaque);
    switch (mode) {
    case BlendMode::Opaque: break;
    case BlendMode::Alpha: glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); break;
    case BlendMode::Additive: glBlendFunc(GL_ONE, GL_ONE); break;
    case BlendMode::Premultiplied: glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA); break;
    }
}

void applyStencil(const StencilState& stencil) {
    setEnabled(GL_STENCIL_TEST, stencil.test);
    STOA_GL_CALL(glStencilFunc(stencil.func, stencil.ref, stencil.readMask));
    STOA_GL_CALL(glStencilOp(stencil.stencilFail, stencil.depthFail, stencil.pass));
    STOA_GL_CALL(glStencilMask(stencil.writeMask));
}

} // namespace

namespace {

bool enabled(GLenum capability) {
    const GLboolean on = glIsEnabled(capability);
    STOA_GL_CHECK("glIsEnabled");
    return on == GL_TRUE;
}

GLint integer(GLenum name) {
    GLint value = 0;
    STOA_GL_CALL(glGetIntegerv(name, &value));
    return value;
}

const char* onOff(bool on) { return on ? "on" : "off"; }

// "GL_DEPTH_TEST is enabled (the pass said: off)".
void compare(std::string& text, const char* name, bool actual, bool wanted) {
    if (actual == wanted) return;
    text += std::string(text.empty() ? "" : ", ") + name + (actual ? " is enabled" : " is disabled") +
            " (the pass said: " + onOff(wanted) + ")";
}

} // namespace

std::string StateCache::differencesFromGl() const {
    if (!m_stateKnown) return "";
    std::string text;
    compare(text, "GL_DEPTH_TEST", enabled(GL_DEPTH_TEST), m_state.depth.test);
    GLboolean depthWrite = GL_TRUE;
    STOA_GL_CALL(glGetBooleanv(GL_DEPTH_WRITEMASK, &depthWrite));
    if ((depthWrite == GL_TRUE) != m_state.depth.write)
        text += std::string(text.empty() ? "" : ", ") + "glDepthMask is " + (depthWrite ? "GL_TRUE" : "GL_FALSE") +
                " (the pass said: depth writes " + onOff(m_state.depth.write) + ")";
    if (static_cast<GLenum>(integer(GL_DEPTH_FUNC)) != m_state.depth.func)
        text += std::string(text.empty() ? "" : ", ") + "glDepthFunc was changed";
    const bool cull = enabled(GL_CULL_FACE);
    compare(text, "GL_CULL_FACE", cull, m_state.cull != CullMode::None);
    if (cull && m_state.cull != CullMode::None &&
        static_cast<GLenum>(integer(GL_CULL_FACE_MODE)) != (m_state.cull == CullMode::Back ? GL_BACK : GL_FRONT))
        text += std::string(text.empty() ? "" : ", ") + "glCullFace was changed";
    compare(text, "GL_BLEND", enabled(GL_BLEND), m_state.blend != BlendMode::Opaque);
    compare(text, "GL_STENCIL_TEST", enabled(GL_STENCIL_TEST), m_state.stencil.test);
    GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    STOA_GL_CALL(glGetBooleanv(GL_COLOR_WRITEMASK, mask));
    if ((mask[0] == GL_TRUE) != m_state.colorMask.red || (mask[1] == GL_TRUE) != m_state.colorMask.green ||
        (mask[2] == GL_TRUE) != m_state.colorMask.blue || (mask[3] == GL_TRUE) != m_state.colorMask.alpha)
        text += std::string(text.empty() ? "" : ", ") + "glColorMask was changed";
    return text;
}

StateCache& StateCache::current() { return GpuResources::current().state(); }

void StateCache::reset() {
    *this = StateCache();
    m_programKnown = true;        // a fresh context: program 0, framebuffer 0
    m_framebuffersKnown = true;
}

void StateCache::forget() {
    m_stateKnown = false;
    m_programKnown = false;
    m_framebuffersKnown = false;
}

template <typename T, typename Set>
void StateCache::update(T& known, const T& wanted, Set set) {
    if (m_stateKnown && known == wanted) {
        ++m_skipped;
        return;
    }
    set(wanted);
    known = wanted;
    ++m_made;
}

void StateCache::apply(const RenderState& state) {
    update(m_state.depth, state.depth, [](const DepthState& depth) {
        setEnabled(GL_DEPTH_TEST, depth.test);
        STOA_GL_CALL(glDepthFunc(depth.func));
        STOA_GL_CALL(glDepthMask(depth.write ? GL_TRUE : GL_FALSE));
    });
    update(m_state.cull, state.cull, applyCull);
    update(m_state.blend, state.blend, applyBlend);
    update(m_state.colorMask, state.colorMask, [](const ColorMask& mask) {
        STOA_GL_CALL(glColorMask(mask.red, mask.green, mask.blue, mask.alpha));
    });
    update(m_state.stencil, state.stencil, applyStencil);
    m_stateKnown = true;
    STOA_GL_CHECK("StateCache::apply()");
}

void StateCache::useProgram(GLuint id) {
    if (m_programKnown && m_program == id) {
        ++m_skipped;
        return;
    }
    STOA_GL_CALL(glUseProgram(id));
    m_program = id;
    m_programKnown = true;
    ++m_made;
}

GLuint StateCache::program() {
    if (!m_programKnown) {
        GLint id = 0;
        STOA_GL_CALL(glGetIntegerv(GL_CURRENT_PROGRAM, &id));
        m_program = static_cast<GLuint>(id);
        m_programKnown = true;
    }
    return m_program;
}

void StateCache::bindFramebuffer(GLuint id) {
    if (m_framebuffersKnown && m_drawFramebuffer == id && m_readFramebuffer == id) {
        ++m_skipped;
        return;
    }
    STOA_GL_CALL(glBindFramebuffer(GL_FRAMEBUFFER, id));
    m_drawFramebuffer = m_readFramebuffer = id;
    m_framebuffersKnown = true;
    ++m_made;
}

void StateCache::bindReadFramebuffer(GLuint id) {
    drawFramebuffer();   // knows both bindings from here on
    if (m_readFramebuffer == id) {
        ++m_skipped;
        return;
    }
    STOA_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, id));
    m_readFramebuffer = id;
    ++m_made;
}

GLuint StateCache::drawFramebuffer() {
    if (!m_framebuffersKnown) {
        GLint draw = 0, read = 0;
        STOA_GL_CALL(glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw));
        STOA_GL_CALL(glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read));
        m_drawFramebuffer = static_cast<GLuint>(draw);
        m_readFramebuffer = static_cast<GLuint>(read);
        m_framebuffersKnown = true;
    }
    return m_drawFramebuffer;
}

GLuint StateCache::readFramebuffer() {
    drawFramebuffer();
    return m_readFramebuffer;
}

void StateCache::programDeleted(GLuint id) {
    // GL keeps a deleted program in use until another is; its name may be
    // handed out again, so the cache must not match a new program against it.
    if (m_programKnown && m_program == id) m_programKnown = false;
}

void StateCache::framebufferDeleted(GLuint id) {
    if (!m_framebuffersKnown) return;
    if (m_drawFramebuffer == id) m_drawFramebuffer = 0;
    if (m_readFramebuffer == id) m_readFramebuffer = 0;
}

} // namespace stoa
