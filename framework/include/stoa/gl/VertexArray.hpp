#pragma once
// A vertex array object: which buffers feed which vertex attributes, and the
// index buffer. Set it up once, bind it to draw.
//
//   VertexArray vertexArray;
//   vertexArray.attribute(0, vertices, 3, GL_FLOAT, sizeof(Vertex), offsetof(Vertex, position));
//   vertexArray.elementBuffer(indices);
//   ...
//   vertexArray.bind();
//   glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);

#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/OpenGL.hpp>

#include <cstddef>

namespace stoa {

class VertexArray {
public:
    /// Creates a vertex array with no attributes. Needs a current context.
    VertexArray();
    ~VertexArray();

    VertexArray(const VertexArray&) = delete;
    VertexArray& operator=(const VertexArray&) = delete;
    VertexArray(VertexArray&& other) noexcept;
    VertexArray& operator=(VertexArray&& other) noexcept;

    void bind() const;
    static void unbind();

    /// Feeds attribute `location` (layout(location = N) in the vertex shader)
    /// from `buffer`: `components` (1..4) values of `type` (GL_FLOAT, ...) per
    /// vertex, `stride` bytes from one vertex to the next, starting `offset`
    /// bytes into the buffer. Integer types are converted to float, divided by
    /// their maximum when `normalized`. Leaves this vertex array bound.
    void attribute(GLuint location, const Buffer& buffer, int components, GLenum type, std::size_t stride,
                   std::size_t offset, bool normalized = false);
    /// The same for integer attributes (ivec, uvec in GLSL): no conversion.
    void integerAttribute(GLuint location, const Buffer& buffer, int components, GLenum type, std::size_t stride,
                          std::size_t offset);
    /// Advances attribute `location` once per `divisor` instances instead of
    /// once per vertex (instanced drawing). Leaves this vertex array bound.
    void divisor(GLuint location, GLuint divisor);
    /// Makes `buffer` this vertex array's index buffer. Leaves it bound.
    void elementBuffer(const Buffer& buffer);

    GLuint id() const { return m_id; } // 0 when moved from or released
    /// Gives up ownership: returns the id and leaves this VertexArray empty.
    GLuint release();

private:
    GLuint m_id = 0;
};

} // namespace stoa
