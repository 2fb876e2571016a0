#include <stoa/gl/Debug.hpp>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

namespace stoa {

namespace {

std::optional<bool> s_checkedOverride;

std::FILE* s_debugOut = stderr;
std::set<std::string> s_debugSeen; // messages printed already (each is printed once)

const char* baseName(const char* path) {
    const char* slash = std::strrchr(path, '/');
    return slash ? slash + 1 : path;
}

// Every error glGetError has queued, as "GL_INVALID_ENUM, GL_INVALID_VALUE";
// empty when there was none. A lost context keeps answering, so stop at 16.
std::string drainErrors() {
    std::string names;
    for (int i = 0; i < 16; ++i) {
        const GLenum error = glGetError();
        if (error == GL_NO_ERROR) break;
        names += std::string(names.empty() ? "" : ", ") + glErrorName(error);
    }
    return names;
}

// "glDrawElements" from "glDrawElements(GL_TRIANGLES, n, ...)".
std::string functionOf(const char* callText) {
    const char* start = callText;
    while (*start == ' ') ++start;
    std::size_t length = 0;
    while (start[length] && start[length] != '(' && start[length] != ' ') ++length;
    return std::string(start, length);
}

const char* sourceName(GLenum source) {
    switch (source) {
    case GL_DEBUG_SOURCE_API: return "API";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
    }
}

const char* typeName(GLenum type) {
    switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    default: return "other";
    }
}

// GL_DEBUG_SEVERITY_* of KHR_debug and the _ARB ones have the same values.
void GLAPIENTRY printDebugMessage(GLenum source, GLenum type, GLuint /*id*/, GLenum severity, GLsizei length,
                                  const GLchar* message, const void* /*user*/) {
    if (severity != GL_DEBUG_SEVERITY_HIGH && severity != GL_DEBUG_SEVERITY_MEDIUM) return;
    // Compile errors reach the user as ShaderError, with file names; the
    // driver's copy of the log would only repeat them with bare line numbers.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    std::string text = length >= 0 ? std::string(message, static_cast<std::size_t>(length)) : std::string(message);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    if (!s_debugSeen.insert(text).second) return;
    std::fprintf(s_debugOut, "GL %s %s (%s severity): %s\n", sourceName(source), typeName(type),
                 severity == GL_DEBUG_SEVERITY_HIGH ? "high" : "medium", text.c_str());
    std::fflush(s_debugOut);
}

} // namespace

bool enableDebugOutput(std::FILE* out) {
    s_debugOut = out ? out : stderr;
    s_debugSeen.clear();
    if (GLEW_KHR_debug && glDebugMessageCallback) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS); // the message arrives inside the call that caused it
        glDebugMessageCallback(&printDebugMessage, nullptr);
        return true;
    }
    if (GLEW_ARB_debug_output && glDebugMessageCallbackARB) {
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS_ARB);
        glDebugMessageCallbackARB(&printDebugMessage, nullptr);
        return true;
    }
    return false;
}

bool checkedMode() {
    if (s_checkedOverride) return *s_checkedOverride;
    static const bool fromEnvironment = [] {
        const char* value = std::getenv("STOA_GL_CHECKED");
        return value && std::strcmp(value, "1") == 0;
    }();
    return fromEnvironment;
}

void setCheckedMode(bool on) { s_checkedOverride = on; }

const char* glErrorName(GLenum error) {
    switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    default: {
        static thread_local char unknown[32];
        std::snprintf(unknown, sizeof unknown, "GL error 0x%04X", error);
        return unknown;
    }
    }
}

void checkGlErrors(const char* what, const char* file, int line) {
    const std::string errors = drainErrors();
    if (errors.empty()) return;
    throw std::runtime_error(std::string(what) + " (" + baseName(file) + ":" + std::to_string(line) + "): " + errors);
}

namespace detail {

void checkBeforeCall(const char* callText, const char* file, int line) {
    const std::string errors = drainErrors();
    if (errors.empty()) return;
    throw std::runtime_error("a GL call before " + functionOf(callText) + " (" + baseName(file) + ":" +
                             std::to_string(line) + ") failed, unchecked: " + errors +
                             ". Wrap the earlier calls in STOA_GL_CALL() or add STOA_GL_CHECK() to find it.");
}

void checkAfterCall(const char* callText, const char* file, int line) {
    checkGlErrors(functionOf(callText).c_str(), file, line);
}

} // namespace detail

} // namespace stoa
