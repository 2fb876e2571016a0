#include <stoa/render/DebugLineRenderer.hpp>

#include <stoa/geometry/DebugLines.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Program.hpp>

#include <cstddef>

namespace stoa {

DebugLineRenderer::DebugLineRenderer(const Program& program) : m_program(program) {}

void DebugLineRenderer::draw(const DebugLines& lines, const glm::mat4& viewProjection) {
    if (lines.vertices().empty()) return;
    m_vertices.upload(lines.vertices(), GL_STREAM_DRAW);
    m_vertexArray.attribute(0, m_vertices, 3, GL_FLOAT, sizeof(LineVertex), offsetof(LineVertex, position));
    m_vertexArray.attribute(1, m_vertices, 3, GL_FLOAT, sizeof(LineVertex), offsetof(LineVertex, color));
    m_program.use();
    m_program.set("uViewProjection", viewProjection);
    m_vertexArray.bind();
    STOA_GL_CALL(glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.vertices().size())));
}

} // namespace stoa
