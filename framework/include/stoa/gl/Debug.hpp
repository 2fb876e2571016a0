#pragma once
// Finding GL errors: the driver's debug messages, and a checked mode that
// names the call that failed.
//
// Checked mode is off by default (glGetError stalls real drivers). Turn it on
// with STOA_GL_CHECKED=1 in the environment or setCheckedMode(true); then
//   STOA_GL_CALL(glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr));
// throws std::runtime_error("glDrawElements (Renderer.cpp:42): GL_INVALID_OPERATION")
// when the call leaves an error behind. STOA_GL_CHECK("after the shadow pass")
// checks whatever came before it. Every Stoa GL wrapper uses them.

#include <stoa/gl/OpenGL.hpp>

#include <cstdio>

namespace stoa {

/// Asks the driver for debug messages (GL_KHR_debug, else GL_ARB_debug_output)
/// and prints those of medium or high severity to `out`, each distinct message
/// once. Shader compiler messages are left out: Program reports them with file
/// names (ShaderError). Returns false when the context offers neither extension.
bool enableDebugOutput(std::FILE* out = stderr);

/// Whether checks run: setCheckedMode()'s last value, else $STOA_GL_CHECKED=1.
bool checkedMode();
void setCheckedMode(bool on);

/// "GL_INVALID_OPERATION" and friends; "GL error 0x...." for unknown codes.
const char* glErrorName(GLenum error);

/// Reads every pending glGetError and, if there was one, throws
/// std::runtime_error("what (file.cpp:line): GL_INVALID_ENUM[, ...]").
/// `file` may be a full path: only its last component is shown. Runs
/// whether or not checked mode is on; the macros below test the mode first.
void checkGlErrors(const char* what, const char* file, int line);

namespace detail {
/// Checked mode, before a call: an error already pending came from an earlier,
/// unchecked call; throws saying so rather than blaming `callText`.
void checkBeforeCall(const char* callText, const char* file, int line);
/// Checked mode, after a call: throws naming the function of `callText`.
void checkAfterCall(const char* callText, const char* file, int line);
} // namespace detail

} // namespace stoa

/// Checks for GL errors left by the calls before it (in checked mode only).
#define STOA_GL_CHECK(what)                                                               \
    do {                                                                                  \
        if (::stoa::checkedMode()) ::stoa::checkGlErrors(what, __FILE__, __LINE__); \
    } while (false)

/// Makes a GL call and, in checked mode, throws naming it if it failed.
/// For a call whose result is needed, write the call, then STOA_GL_CHECK("glMapBuffer").
#define STOA_GL_CALL(call)                                                                         \
    do {                                                                                           \
        const bool stoaGlChecked = ::stoa::checkedMode();                                      \
        if (stoaGlChecked) ::stoa::detail::checkBeforeCall(#call, __FILE__, __LINE__);         \
        call;                                                                                      \
        if (stoaGlChecked) ::stoa::detail::checkAfterCall(#call, __FILE__, __LINE__);          \
    } while (false)
