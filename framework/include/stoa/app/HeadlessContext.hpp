#pragma once
// An OpenGL 3.3 core context without a window, rendered by Mesa's llvmpipe on
// the CPU, so that a student's laptop and the grading server draw the same
// pixels. Two backends:
//   OSMesa  libOSMesa, loaded at run time (dlopen), never linked: Mesa 25.1
//           dropped it, and a binary built here must still run there.
//   EGL     a surfaceless EGL display (EGL_MESA_platform_surfaceless). To get
//           llvmpipe where Mesa also drives a GPU, it sets
//           LIBGL_ALWAYS_SOFTWARE=1 in the environment unless already set.
// There is no default framebuffer to speak of (OSMesa's is 1x1, EGL has none):
// render into a stoa::Framebuffer and read it back from there.
//
//   stoa::HeadlessContext context;               // $STOA_HEADLESS, else OSMesa, else EGL
//   stoa::Framebuffer target(256, 256);
//   stoa::beginPass(stoa::passInto(target));     // RenderPass.hpp
//   ...draw...
//   stoa::Image frame = target.readColor();

#include <memory>
#include <optional>
#include <string>

namespace stoa {

class GpuResources;

namespace detail {
class HeadlessState; // the backend's handles (OSMesa or EGL), defined in HeadlessContext.cpp
}

enum class HeadlessBackend { OSMesa, Egl };

/// "osmesa" or "egl", as $STOA_HEADLESS and the command-line flags spell them.
const char* toString(HeadlessBackend backend);

/// "osmesa" -> OSMesa, "egl" -> Egl. Anything else throws
/// InputError("", 0, "unknown headless backend 'x' (valid: osmesa, egl)").
HeadlessBackend parseHeadlessBackend(const std::string& name);

class HeadlessContext {
public:
    /// Creates the context and makes it current on this thread, then routes
    /// every GL entry point to it (stoa::gl::loadFunctions). The backend is
    /// `backend` when given, else $STOA_HEADLESS ("osmesa" or "egl"), else
    /// OSMesa where libOSMesa.so.8 loads, else EGL.
    /// Throws std::runtime_error naming the library or call that failed and
    /// what to install; InputError when $STOA_HEADLESS names no backend.
    /// One HeadlessContext at a time per process: the GL entry points are
    /// global, so a second live context is a programming error (assert).
    explicit HeadlessContext(std::optional<HeadlessBackend> backend = std::nullopt);
    /// Releases and destroys the context; another may be created afterwards.
    ~HeadlessContext();

    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;
    HeadlessContext(HeadlessContext&&) = delete;
    HeadlessContext& operator=(HeadlessContext&&) = delete;

    HeadlessBackend backend() const { return m_backend; }

    /// GL_RENDERER and GL_VERSION of the context, e.g.
    /// "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6".
    std::string description() const;

    /// Whether a context of this backend can be created here: for OSMesa,
    /// whether the library loads; for EGL, whether a surfaceless (or default)
    /// display initialises. Creates no context.
    static bool isAvailable(HeadlessBackend backend);

    /// The backend a default-constructed HeadlessContext would use.
    static HeadlessBackend defaultBackend();

private:
    HeadlessBackend m_backend;
    std::unique_ptr<detail::HeadlessState> m_state;
    std::unique_ptr<GpuResources> m_resources;   // the context's caches (stoa/gl/GpuResources.hpp)
};

} // namespace stoa
