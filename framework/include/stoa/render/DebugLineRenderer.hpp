#pragma once
// Draws DebugLines (geometry/DebugLines.hpp) as GL_LINES with
// shaders/debug/lines.vert and lines.frag, in the pass that is current: the caller's
// RenderState decides whether they are depth tested (see RenderPass.hpp).
//
//   const Program& program = resources.loadProgram("debug/lines.vert", "debug/lines.frag");
//   DebugLineRenderer debug(program);
//   debug.draw(lines, camera.projection * camera.view);

#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/VertexArray.hpp>

#include <glm/mat4x4.hpp>

namespace stoa {

class DebugLines;
class Program;

class DebugLineRenderer {
public:
    /// `program` is shaders/debug/lines.vert with lines.frag (or one with the same
    /// attributes and uViewProjection); it must outlive the renderer.
    explicit DebugLineRenderer(const Program& program);

    /// Uploads the segments and draws them; nothing when there are none.
    void draw(const DebugLines& lines, const glm::mat4& viewProjection);

private:
    const Program& m_program;
    Buffer m_vertices{GL_ARRAY_BUFFER};
    VertexArray m_vertexArray;
};

} // namespace stoa
