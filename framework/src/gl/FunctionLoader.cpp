#include <stoa/gl/FunctionLoader.hpp>
#include <stoa/gl/OpenGL.hpp>

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace stoa::gl {
namespace {

ProcLoader g_loader = nullptr;

ProcAddress realGlxGetProcAddress(const char* name) {
    using Function = ProcAddress (*)(const GLubyte*);
    // RTLD_NEXT skips this program's own definition below and finds libGL's.
    static Function real = reinterpret_cast<Function>(dlsym(RTLD_NEXT, "glXGetProcAddressARB"));
    return real ? real(reinterpret_cast<const GLubyte*>(name)) : nullptr;
}

ProcAddress lookUp(const char* name) {
    // GLX functions always come from libGL: GLEW asks for them after the GL ones,
    // and on a headless context they must answer "no display" rather than crash.
    if (!g_loader || std::strncmp(name, "glX", 3) == 0) return realGlxGetProcAddress(name);
    return g_loader(name);
}

} // namespace
} // namespace stoa::gl

// The OpenGL 1.0 and 1.1 functions still in the 3.3 core profile. Each one is
// defined here with the same signature and forwards to a pointer that
// loadFunctions() fills from the current backend.
#define STOA_GL_CORE_1_1(X)                                                                                   \
    X(void, glCullFace, (GLenum a), (a))                                                                      \
    X(void, glFrontFace, (GLenum a), (a))                                                                     \
    X(void, glHint, (GLenum a, GLenum b), (a, b))                                                             \
    X(void, glLineWidth, (GLfloat a), (a))                                                                    \
    X(void, glPointSize, (GLfloat a), (a))                                                                    \
    X(void, glPolygonMode, (GLenum a, GLenum b), (a, b))                                                      \
    X(void, glScissor, (GLint a, GLint b, GLsizei c, GLsizei d), (a, b, c, d))                                \
    X(void, glTexParameterf, (GLenum a, GLenum b, GLfloat c), (a, b, c))                                      \
    X(void, glTexParameterfv, (GLenum a, GLenum b, const GLfloat* c), (a, b, c))                              \
    X(void, glTexParameteri, (GLenum a, GLenum b, GLint c), (a, b, c))                                        \
    X(void, glTexParameteriv, (GLenum a, GLenum b, const GLint* c), (a, b, c))                                \
    X(void, glTexImage1D, (GLenum a, GLint b, GLint c, GLsizei d, GLint e, GLenum f, GLenum g, const void* h), \
      (a, b, c, d, e, f, g, h))                                                                               \
    X(void, glTexImage2D,                                                                                     \
      (GLenum a, GLint b, GLint c, GLsizei d, GLsizei e, GLint f, GLenum g, GLenum h, const void* i),         \
      (a, b, c, d, e, f, g, h, i))                                                                            \
    X(void, glDrawBuffer, (GLenum a), (a))                                                                    \
    X(void, glClear, (GLbitfield a), (a))                                                                     \
    X(void, glClearColor, (GLfloat a, GLfloat b, GLfloat c, GLfloat d), (a, b, c, d))                         \
    X(void, glClearStencil, (GLint a), (a))                                                                   \
    X(void, glClearDepth, (GLdouble a), (a))                                                                  \
    X(void, glStencilMask, (GLuint a), (a))                                                                   \
    X(void, glColorMask, (GLboolean a, GLboolean b, GLboolean c, GLboolean d), (a, b, c, d))                  \
    X(void, glDepthMask, (GLboolean a), (a))                                                                  \
    X(void, glDisable, (GLenum a), (a))                                                                       \
    X(void, glEnable, (GLenum a), (a))                                                                        \
    X(void, glFinish, (), ())                                                                                 \
    X(void, glFlush, (), ())                                                                                  \
    X(void, glBlendFunc, (GLenum a, GLenum b), (a, b))                                                        \
    X(void, glLogicOp, (GLenum a), (a))                                                                       \
    X(void, glStencilFunc, (GLenum a, GLint b, GLuint c), (a, b, c))                                          \
    X(void, glStencilOp, (GLenum a, GLenum b, GLenum c), (a, b, c))                                           \
    X(void, glDepthFunc, (GLenum a), (a))                                                                     \
    X(void, glPixelStoref, (GLenum a, GLfloat b), (a, b))                                                     \
    X(void, glPixelStorei, (GLenum a, GLint b), (a, b))                                                       \
    X(void, glReadBuffer, (GLenum a), (a))                                                                    \
    X(void, glReadPixels, (GLint a, GLint b, GLsizei c, GLsizei d, GLenum e, GLenum f, void* g),              \
      (a, b, c, d, e, f, g))                                                                                  \
    X(void, glGetBooleanv, (GLenum a, GLboolean* b), (a, b))                                                  \
    X(void, glGetDoublev, (GLenum a, GLdouble* b), (a, b))                                                    \
    X(GLenum, glGetError, (), ())                                                                             \
    X(void, glGetFloatv, (GLenum a, GLfloat* b), (a, b))                                                      \
    X(void, glGetIntegerv, (GLenum a, GLint* b), (a, b))                                                      \
    X(const GLubyte*, glGetString, (GLenum a), (a))                                                           \
    X(void, glGetTexImage, (GLenum a, GLint b, GLenum c, GLenum d, void* e), (a, b, c, d, e))                 \
    X(void, glGetTexParameterfv, (GLenum a, GLenum b, GLfloat* c), (a, b, c))                                 \
    X(void, glGetTexParameteriv, (GLenum a, GLenum b, GLint* c), (a, b, c))                                   \
    X(void, glGetTexLevelParameterfv, (GLenum a, GLint b, GLenum c, GLfloat* d), (a, b, c, d))                \
    X(void, glGetTexLevelParameteriv, (GLenum a, GLint b, GLenum c, GLint* d), (a, b, c, d))                  \
    X(GLboolean, glIsEnabled, (GLenum a), (a))                                                                \
    X(void, glDepthRange, (GLdouble a, GLdouble b), (a, b))                                                   \
    X(void, glViewport, (GLint a, GLint b, GLsizei c, GLsizei d), (a, b, c, d))                               \
    X(void, glDrawArrays, (GLenum a, GLint b, GLsizei c), (a, b, c))                                          \
    X(void, glDrawElements, (GLenum a, GLsizei b, GLenum c, const void* d), (a, b, c, d))                     \
    X(void, glPolygonOffset, (GLfloat a, GLfloat b), (a, b))                                                  \
    X(void, glCopyTexImage1D, (GLenum a, GLint b, GLenum c, GLint d, GLint e, GLsizei f, GLint g),            \
      (a, b, c, d, e, f, g))                                                                                  \
    X(void, glCopyTexImage2D, (GLenum a, GLint b, GLenum c, GLint d, GLint e, GLsizei f, GLsizei g, GLint h), \
      (a, b, c, d, e, f, g, h))                                                                               \
    X(void, glCopyTexSubImage1D, (GLenum a, GLint b, GLint c, GLint d, GLint e, GLsizei f),                   \
      (a, b, c, d, e, f))                                                                                     \
    X(void, glCopyTexSubImage2D,                                                                              \
      (GLenum a, GLint b, GLint c, GLint d, GLint e, GLint f, GLsizei g, GLsizei h), (a, b, c, d, e, f, g, h)) \
    X(void, glTexSubImage1D, (GLenum a, GLint b, GLint c, GLsizei d, GLenum e, GLenum f, const void* g),      \
      (a, b, c, d, e, f, g))                                                                                  \
    X(void, glTexSubImage2D,                                                                                  \
      (GLenum a, GLint b, GLint c, GLint d, GLsizei e, GLsizei f, GLenum g, GLenum h, const void* i),         \
      (a, b, c, d, e, f, g, h, i))                                                                            \
    X(void, glBindTexture, (GLenum a, GLuint b), (a, b))                                                      \
    X(void, glDeleteTextures, (GLsizei a, const GLuint* b), (a, b))                                           \
    X(void, glGenTextures, (GLsizei a, GLuint* b), (a, b))                                                    \
    X(GLboolean, glIsTexture, (GLuint a), (a))

namespace {
#define STOA_DECLARE_POINTER(ret, name, params, args) ret(GLAPIENTRY* s_##name) params = nullptr;
STOA_GL_CORE_1_1(STOA_DECLARE_POINTER)
#undef STOA_DECLARE_POINTER

// A call before loadFunctions() (freeglut setting up its window, say) resolves
// its pointer through GLX, as libGL itself would have.
template <typename Pointer>
Pointer resolve(Pointer& pointer, const char* name) {
    if (!pointer) pointer = reinterpret_cast<Pointer>(stoa::gl::lookUp(name));
    if (!pointer) {
        std::fprintf(stderr, "stoa: the OpenGL function %s is unavailable in this context\n", name);
        std::abort();
    }
    return pointer;
}
} // namespace

extern "C" {

#define STOA_DEFINE_TRAMPOLINE(ret, name, params, args) \
    ret GLAPIENTRY name params { return resolve(s_##name, #name) args; }
STOA_GL_CORE_1_1(STOA_DEFINE_TRAMPOLINE)
#undef STOA_DEFINE_TRAMPOLINE

// GLEW and freeglut call these by name; the program's definitions take
// precedence over libGL's.
stoa::gl::ProcAddress glXGetProcAddressARB(const GLubyte* name) {
    return stoa::gl::lookUp(reinterpret_cast<const char*>(name));
}
stoa::gl::ProcAddress glXGetProcAddress(const GLubyte* name) {
    return stoa::gl::lookUp(reinterpret_cast<const char*>(name));
}

} // extern "C"

namespace stoa::gl {

ProcLoader glxLoader() { return &realGlxGetProcAddress; }

void loadFunctions(ProcLoader loader, const char* backendName) {
    g_loader = loader;
    std::string missing;
#define STOA_LOAD_POINTER(ret, name, params, args)                                   \
    s_##name = reinterpret_cast<ret(GLAPIENTRY*) params>(lookUp(#name));             \
    if (!s_##name) missing += std::string(missing.empty() ? "" : ", ") + #name;
    STOA_GL_CORE_1_1(STOA_LOAD_POINTER)
#undef STOA_LOAD_POINTER
    if (!missing.empty())
        throw std::runtime_error(std::string(backendName) + ": the context does not provide " + missing);

    glewExperimental = GL_TRUE;
    const GLenum status = glewInit();
    // Without a GLX display (OSMesa, EGL) glewInit() reports NO_GLX_DISPLAY, or
    // GLX_VERSION_11_ONLY, after it has loaded every GL function: success here.
    if (status != GLEW_OK && status != GLEW_ERROR_NO_GLX_DISPLAY && status != GLEW_ERROR_GLX_VERSION_11_ONLY)
        throw std::runtime_error(std::string(backendName) + ": glewInit() failed: " +
                                 reinterpret_cast<const char*>(glewGetErrorString(status)));
    if (!GLEW_VERSION_3_3 || !glGenVertexArrays)
        throw std::runtime_error(std::string(backendName) + ": OpenGL 3.3 core is required, the context offers " +
                                 reinterpret_cast<const char*>(glGetString(GL_VERSION)));
    // glewInit() may leave GL_INVALID_ENUM behind (it queries GL_EXTENSIONS); clear it.
    while (glGetError() != GL_NO_ERROR) {
    }
}

} // namespace stoa::gl
