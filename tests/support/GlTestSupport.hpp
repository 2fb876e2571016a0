#pragma once
// Shared pieces of the GL tests: fixture folders, pixel comparison, and a
// few 2D triangles to draw. Every GL test creates its own HeadlessContext
// (the backend comes from $STOA_HEADLESS, as CTest sets it).

#include "catch.hpp"

#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/VertexArray.hpp>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace stoa::test {

inline const std::filesystem::path glShadersDir = std::filesystem::path(STOA_TEST_DATA_DIR) / "gl" / "shaders";

inline void writeTextFile(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

/// Every channel within `tolerance` levels (llvmpipe rounds as it likes).
inline bool near(glm::u8vec4 a, glm::u8vec4 b, int tolerance = 1) {
    for (int i = 0; i < 4; ++i)
        if (std::abs(int(a[i]) - int(b[i])) > tolerance) return false;
    return true;
}

inline std::string describe(glm::u8vec4 c) {
    std::ostringstream out;
    out << "(" << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ", " << int(c.a) << ")";
    return out.str();
}

/// Clip-space 2D triangles in a buffer, drawn through attribute 0
/// (shaders/position2d.vert).
class Triangles2D {
public:
    explicit Triangles2D(std::vector<glm::vec2> corners) : m_count(static_cast<GLsizei>(corners.size())) {
        m_corners.upload(corners);
        m_vertexArray.attribute(0, m_corners, 2, GL_FLOAT, sizeof(glm::vec2), 0);
    }
    /// The rectangle [x0, x1] x [y0, y1] in clip space.
    static Triangles2D rectangle(float x0, float y0, float x1, float y1) {
        return Triangles2D({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}});
    }
    void draw() const {
        m_vertexArray.bind();
        glDrawArrays(GL_TRIANGLES, 0, m_count);
    }

private:
    Buffer m_corners{GL_ARRAY_BUFFER};
    VertexArray m_vertexArray;
    GLsizei m_count;
};

/// Drains glGetError; the first error, or GL_NO_ERROR.
inline GLenum takeGlError() {
    const GLenum first = glGetError();
    while (glGetError() != GL_NO_ERROR) {
    }
    return first;
}

} // namespace stoa::test
