#pragma once
// One compiled shader stage: the compile step of a Program. Most code never
// names it and calls Program::fromFiles() instead.

#include <stoa/core/InputError.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/ShaderSource.hpp>

#include <string>

namespace stoa {

/// A shader that does not compile or a program that does not link. file() and
/// line() name the first error (line 0 for link errors); message() starts with
/// "Program: cannot compile fragment shader ..." or "Program: cannot link ..."
/// and holds every line of the driver's log, rewritten to name files
/// (ShaderSource::translateLog).
class ShaderError : public InputError {
public:
    ShaderError(std::string file, int line, std::string message, std::string log);

    /// The driver's log with file names, without the first line of message().
    const std::string& log() const { return m_log; }

private:
    std::string m_log;
};

/// "vertex", "geometry", "fragment" for GL_VERTEX_SHADER etc.
const char* stageName(GLenum stage);

class Shader {
public:
    /// No shader; no GL call.
    Shader() = default;
    /// Compiles `source` as `stage` (GL_VERTEX_SHADER, GL_GEOMETRY_SHADER or
    /// GL_FRAGMENT_SHADER). Throws ShaderError when it does not compile.
    Shader(GLenum stage, const ShaderSource& source);
    ~Shader();

    Shader(const Shader&) = delete;
    Shader& operator=(const Shader&) = delete;
    Shader(Shader&& other) noexcept;
    Shader& operator=(Shader&& other) noexcept;

    GLenum stage() const { return m_stage; }
    GLuint id() const { return m_id; } // 0 when empty
    /// Gives up ownership: returns the id and leaves this Shader empty.
    GLuint release();

private:
    GLenum m_stage = 0;
    GLuint m_id = 0;
};

} // namespace stoa
