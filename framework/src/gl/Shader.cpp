#include <stoa/gl/Shader.hpp>

#include <stoa/gl/Debug.hpp>

#include <utility>

namespace stoa {

ShaderError::ShaderError(std::string file, int line, std::string message, std::string log)
    : InputError(std::move(file), line, std::move(message)), m_log(std::move(log)) {}

const char* stageName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_GEOMETRY_SHADER: return "geometry";
    case GL_FRAGMENT_SHADER: return "fragment";
    default: return "unknown";
    }
}

namespace {

std::string infoLog(GLuint shader) {
    GLint length = 0;
    STOA_GL_CALL(glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length));
    if (length <= 1) return "";
    std::string log(static_cast<std::size_t>(length), '\0');
    STOA_GL_CALL(glGetShaderInfoLog(shader, length, nullptr, log.data()));
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

// Compiles `text`; returns the id, or 0 with the driver's log in `log`.
GLuint compile(GLenum stage, const std::string& text, std::string& log) {
    const GLuint id = glCreateShader(stage);
    STOA_GL_CHECK("glCreateShader");
    const char* source = text.c_str();
    STOA_GL_CALL(glShaderSource(id, 1, &source, nullptr));
    STOA_GL_CALL(glCompileShader(id));
    GLint compiled = GL_FALSE;
    STOA_GL_CALL(glGetShaderiv(id, GL_COMPILE_STATUS, &compiled));
    if (compiled) return id;
    log = infoLog(id);
    glDeleteShader(id);
    return 0;
}

} // namespace

Shader::Shader(GLenum stage, const ShaderSource& source) : m_stage(stage) {
    std::string log;
    m_id = compile(stage, source.text(), log);
    if (m_id) return;
    std::string translated = source.translateLog(log);
    while (!translated.empty() && (translated.back() == '\n' || translated.back() == ' ')) translated.pop_back();
    const std::string top = source.files().empty() ? std::string("?") : source.files()[0].generic_string();
    const std::optional<ShaderLocation> first = source.firstError(log);
    throw ShaderError(first ? first->file : top, first ? first->line : 0,
                      std::string("Program: cannot compile ") + stageName(stage) + " shader " + top + ":\n" +
                          translated,
                      translated);
}

Shader::~Shader() {
    if (m_id) glDeleteShader(m_id);
}

Shader::Shader(Shader&& other) noexcept
    : m_stage(other.m_stage), m_id(std::exchange(other.m_id, 0)) {}

Shader& Shader::operator=(Shader&& other) noexcept {
    if (this != &other) {
        if (m_id) glDeleteShader(m_id);
        m_stage = other.m_stage;
        m_id = std::exchange(other.m_id, 0);
    }
    return *this;
}

GLuint Shader::release() { return std::exchange(m_id, 0); }

} // namespace stoa
