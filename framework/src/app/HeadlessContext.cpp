#include <stoa/app/HeadlessContext.hpp>
#include <stoa/gl/GpuResources.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/gl/FunctionLoader.hpp>
#include <stoa/gl/OpenGL.hpp>

// Keep X11's macros (None, Bool, Status, ...) out: nothing here needs a display.
#define EGL_NO_X11
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace stoa {

namespace detail {
class HeadlessState {
public:
    virtual ~HeadlessState() = default;
};
} // namespace detail

namespace {

// Only one context may live at a time: loadFunctions() points every GL entry
// point of the process at it.
std::optional<HeadlessBackend> s_liveBackend;

// OSMesa
// The few declarations of GL/osmesa.h used here. They are Mesa's stable ABI;
// declaring them here keeps the header optional and avoids its <GL/gl.h>.
using OSMesaContext = struct osmesa_context*;
constexpr int kOsMesaFormat = 0x22;
constexpr int kOsMesaDepthBits = 0x30;
constexpr int kOsMesaStencilBits = 0x31;
constexpr int kOsMesaProfile = 0x33;
constexpr int kOsMesaCoreProfile = 0x34;
constexpr int kOsMesaContextMajorVersion = 0x36;
constexpr int kOsMesaContextMinorVersion = 0x37;

struct OsMesaLibrary {
    void* handle = nullptr;
    std::string problem; // why it cannot be used, when handle is null
    OSMesaContext (*createContextAttribs)(const int* attributes, OSMesaContext share) = nullptr;
    GLboolean (*makeCurrent)(OSMesaContext context, void* buffer, GLenum type, GLsizei width, GLsizei height) = nullptr;
    void (*destroyContext)(OSMesaContext context) = nullptr;
    gl::ProcAddress (*getProcAddress)(const char* name) = nullptr;
};

template <typename Function>
bool findSymbol(void* handle, const char* name, Function& function, std::string& missing) {
    function = reinterpret_cast<Function>(dlsym(handle, name));
    if (!function) missing += std::string(missing.empty() ? "" : ", ") + name;
    return function != nullptr;
}

OsMesaLibrary openOsMesa() {
    OsMesaLibrary library;
    std::string reasons;
    // RTLD_LOCAL: OSMesa's own GL symbols must not shadow the ones the program
    // defines (FunctionLoader.cpp); everything is reached through dlsym.
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"}) {
        library.handle = dlopen(name, RTLD_NOW | RTLD_LOCAL);
        if (library.handle) break;
        reasons += std::string(reasons.empty() ? "" : "; ") + dlerror();
    }
    if (!library.handle) {
        library.problem = "cannot load libOSMesa.so.8 or libOSMesa.so (" + reasons + ")";
        return library;
    }
    std::string missing;
    findSymbol(library.handle, "OSMesaCreateContextAttribs", library.createContextAttribs, missing);
    findSymbol(library.handle, "OSMesaMakeCurrent", library.makeCurrent, missing);
    findSymbol(library.handle, "OSMesaDestroyContext", library.destroyContext, missing);
    findSymbol(library.handle, "OSMesaGetProcAddress", library.getProcAddress, missing);
    if (!missing.empty()) {
        // The library stays loaded (never dlclose Mesa): its threads may outlive us.
        library.handle = nullptr;
        library.problem = "libOSMesa lacks " + missing + " (Mesa 11.2 or newer is needed)";
    }
    return library;
}

// Loaded once, never unloaded.
const OsMesaLibrary& osMesaLibrary() {
    static const OsMesaLibrary library = openOsMesa();
    return library;
}

gl::ProcAddress osMesaProcAddress(const char* name) { return osMesaLibrary().getProcAddress(name); }

/// The context asked for: OpenGL 3.3 core, or what STOA_GL_CONTEXT names,
/// "MAJOR.MINOR" with "-forward" for a forward-compatible one ("4.1-forward" is
/// what macOS gives, to try the labs' shaders there without a Mac).
struct ContextRequest {
    int major = 3;
    int minor = 3;
    bool forwardCompatible = false;
    std::string text() const {
        return std::to_string(major) + "." + std::to_string(minor) + " core" + (forwardCompatible ? ", forward-compatible" : "");
    }
};

ContextRequest contextRequest() {
    ContextRequest request;
    const char* chosen = std::getenv("STOA_GL_CONTEXT");
    if (!chosen || !*chosen) return request;
    std::string text = chosen;
    const std::string forward = "-forward";
    if (text.size() > forward.size() && text.compare(text.size() - forward.size(), forward.size(), forward) == 0) {
        request.forwardCompatible = true;
        text.resize(text.size() - forward.size());
    }
    const bool valid = text.size() == 3 && text[0] >= '3' && text[0] <= '4' && text[1] == '.' && text[2] >= '0' && text[2] <= '6';
    if (!valid || (text[0] == '3' && text[2] < '2'))
        throw std::runtime_error("STOA_GL_CONTEXT='" + std::string(chosen) +
                                 "': expected a core version from 3.2 to 4.6, such as 3.3 or 4.1, with -forward for a "
                                 "forward-compatible context (4.1-forward is what macOS gives)");
    request.major = text[0] - '0';
    request.minor = text[2] - '0';
    return request;
}

[[noreturn]] void failOsMesa(const std::string& what) {
    throw std::runtime_error("HeadlessContext (osmesa): " + what +
                             ". Install Mesa's OSMesa (Debian/Ubuntu: libosmesa6, Fedora: mesa-libOSMesa); "
                             "Mesa 25.1 and later ship none, use STOA_HEADLESS=egl there.");
}

class OsMesaState final : public detail::HeadlessState {
public:
    OsMesaState() {
        const OsMesaLibrary& library = osMesaLibrary();
        if (!library.handle) failOsMesa(library.problem);
        const ContextRequest request = contextRequest();
        if (request.forwardCompatible) failOsMesa("OSMesa makes no forward-compatible context; use STOA_HEADLESS=egl");
        const int attributes[] = {kOsMesaFormat, GL_RGBA,
                                  kOsMesaDepthBits, 24,
                                  kOsMesaStencilBits, 8,
                                  kOsMesaProfile, kOsMesaCoreProfile,
                                  kOsMesaContextMajorVersion, request.major,
                                  kOsMesaContextMinorVersion, request.minor,
                                  0};
        m_context = library.createContextAttribs(attributes, nullptr);
        if (!m_context) failOsMesa("OSMesaCreateContextAttribs() refused an OpenGL " + request.text() + " context");
        // OSMesa draws its default framebuffer into client memory; nothing is
        // drawn there (Framebuffer objects take the rendering), so 1x1 will do.
        if (!library.makeCurrent(m_context, m_pixels, GL_UNSIGNED_BYTE, 1, 1)) {
            library.destroyContext(m_context);
            failOsMesa("OSMesaMakeCurrent() failed");
        }
    }

    ~OsMesaState() override {
        const OsMesaLibrary& library = osMesaLibrary();
        library.makeCurrent(nullptr, nullptr, 0, 0, 0);
        library.destroyContext(m_context);
    }

    OsMesaState(const OsMesaState&) = delete;
    OsMesaState& operator=(const OsMesaState&) = delete;

private:
    OSMesaContext m_context = nullptr;
    unsigned char m_pixels[4] = {}; // the 1x1 RGBA default framebuffer
};

// EGL

const char* eglErrorName(EGLint error) {
    switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
    }
}

[[noreturn]] void failEgl(const std::string& call) {
    throw std::runtime_error("HeadlessContext (egl): " + call + " failed (" + eglErrorName(eglGetError()) +
                             "). Install Mesa's EGL and software driver (Debian/Ubuntu: libegl1 libegl-mesa0 "
                             "libgl1-mesa-dri; Fedora: mesa-libEGL mesa-dri-drivers), or use STOA_HEADLESS=osmesa.");
}

bool hasExtension(const char* list, const char* extension) {
    if (!list) return false;
    const std::size_t length = std::strlen(extension);
    for (const char* at = std::strstr(list, extension); at; at = std::strstr(at + 1, extension)) {
        const bool startsWord = at == list || at[-1] == ' ';
        const bool endsWord = at[length] == ' ' || at[length] == '\0';
        if (startsWord && endsWord) return true;
    }
    return false;
}

gl::ProcAddress eglProcAddress(const char* name) { return eglGetProcAddress(name); }

// The surfaceless Mesa display when the client offers it, else the default one.
// Must be followed by eglInitialize().
EGLDisplay openEglDisplay() {
    // Graded frames come from llvmpipe everywhere: ask Mesa for its software
    // rasteriser unless the user decided otherwise (LIBGL_ALWAYS_SOFTWARE=0).
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", /*overwrite=*/0);
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (getPlatformDisplay) {
            EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (display != EGL_NO_DISPLAY) return display;
        }
    }
    return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

class EglState final : public detail::HeadlessState {
public:
    EglState() {
        m_display = openEglDisplay();
        if (m_display == EGL_NO_DISPLAY) failEgl("eglGetDisplay()");
        EGLint major = 0, minor = 0;
        if (!eglInitialize(m_display, &major, &minor)) failEgl("eglInitialize()");
        try {
            createContext();
        } catch (...) {
            eglTerminate(m_display);
            throw;
        }
    }

    ~EglState() override {
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(m_display, m_context);
        // The display stays initialized until the process exits (EGL displays are
        // per process; initializing one again is a no-op). Terminating it makes
        // Mesa unload its driver, after which LeakSanitizer can no longer tell the
        // driver's own small allocations from ours.
        eglReleaseThread();
    }

    EglState(const EglState&) = delete;
    EglState& operator=(const EglState&) = delete;

private:
    void createContext() {
        if (!eglBindAPI(EGL_OPENGL_API)) failEgl("eglBindAPI(EGL_OPENGL_API)");
        // Any config that renders desktop OpenGL; with EGL_KHR_no_config_context
        // none is needed at all, as nothing is drawn to an EGL surface.
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = EGL_NO_CONFIG_KHR;
        EGLint configCount = 0;
        if (!eglChooseConfig(m_display, configAttributes, &config, 1, &configCount) || configCount == 0) {
            if (!hasExtension(eglQueryString(m_display, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
                failEgl("eglChooseConfig() for an OpenGL config");
            config = EGL_NO_CONFIG_KHR;
        }
        const ContextRequest request = contextRequest();
        // The forward-compatible attribute is EGL 1.5's: named only when asked for,
        // so that the default request stays what an EGL 1.4 takes.
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, request.major,
                                            EGL_CONTEXT_MINOR_VERSION, request.minor,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                            request.forwardCompatible ? EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE : EGL_NONE,
                                            EGL_TRUE,
                                            EGL_NONE};
        m_context = eglCreateContext(m_display, config, EGL_NO_CONTEXT, contextAttributes);
        if (m_context == EGL_NO_CONTEXT) failEgl("eglCreateContext() for OpenGL " + request.text());
        if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context)) {
            eglDestroyContext(m_display, m_context);
            failEgl("eglMakeCurrent() without a surface (EGL_KHR_surfaceless_context)");
        }
    }

    EGLDisplay m_display = EGL_NO_DISPLAY;
    EGLContext m_context = EGL_NO_CONTEXT;
};

bool eglDisplayInitialises() {
    EGLDisplay display = openEglDisplay();
    if (display == EGL_NO_DISPLAY) return false;
    EGLint major = 0, minor = 0;
    // Left initialized on purpose, as in ~EglState().
    return eglInitialize(display, &major, &minor) == EGL_TRUE;
}

} // namespace

const char* toString(HeadlessBackend backend) {
    switch (backend) {
    case HeadlessBackend::OSMesa: return "osmesa";
    case HeadlessBackend::Egl: return "egl";
    }
    return "unknown";
}

HeadlessBackend parseHeadlessBackend(const std::string& name) {
    if (name == "osmesa") return HeadlessBackend::OSMesa;
    if (name == "egl") return HeadlessBackend::Egl;
    throw InputError("", 0, "unknown headless backend '" + name + "' (valid: osmesa, egl)");
}

HeadlessBackend HeadlessContext::defaultBackend() {
    if (const char* chosen = std::getenv("STOA_HEADLESS"); chosen && *chosen) {
        try {
            return parseHeadlessBackend(chosen);
        } catch (const InputError& error) {
            throw InputError("", 0, "STOA_HEADLESS: " + error.message());
        }
    }
    return osMesaLibrary().handle ? HeadlessBackend::OSMesa : HeadlessBackend::Egl;
}

bool HeadlessContext::isAvailable(HeadlessBackend backend) {
    switch (backend) {
    case HeadlessBackend::OSMesa: return osMesaLibrary().handle != nullptr;
    // Initialising and terminating the display would end a live EGL context.
    case HeadlessBackend::Egl: return s_liveBackend == HeadlessBackend::Egl || eglDisplayInitialises();
    }
    return false;
}

HeadlessContext::HeadlessContext(std::optional<HeadlessBackend> backend)
    : m_backend(backend ? *backend : defaultBackend()) {
    STOA_ASSERT(!s_liveBackend, "HeadlessContext(): another HeadlessContext is alive in this process. "
                                 "Destroy it first: the GL entry points follow one context at a time.");
    if (m_backend == HeadlessBackend::OSMesa) {
        m_state = std::make_unique<OsMesaState>();
        gl::loadFunctions(&osMesaProcAddress, "OSMesa");
    } else {
        m_state = std::make_unique<EglState>();
        gl::loadFunctions(&eglProcAddress, "EGL");
    }
    s_liveBackend = m_backend;
    m_resources = std::make_unique<GpuResources>();
    GpuResources::makeCurrent(m_resources.get());
}

HeadlessContext::~HeadlessContext() {
    m_resources.reset();   // its GL objects first, while the context is alive
    m_state.reset();
    s_liveBackend.reset();
}

std::string HeadlessContext::description() const {
    const auto text = [](GLenum name) {
        const GLubyte* value = glGetString(name);
        return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
    };
    return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

} // namespace stoa
