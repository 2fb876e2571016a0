#pragma once
// A GL buffer object: vertex data, indices, uniform blocks.
//
//   Buffer vertices(GL_ARRAY_BUFFER);
//   vertices.upload(mesh.vertices);                     // a std::vector, or (pointer, bytes)
//   vertexArray.attribute(0, vertices, 3, GL_FLOAT, sizeof(Vertex), offsetof(Vertex, position));

#include <stoa/gl/OpenGL.hpp>

#include <cstddef>
#include <vector>

namespace stoa {

class Buffer {
public:
    /// No buffer; no GL call.
    Buffer() = default;
    /// Creates an empty buffer that bind() binds to `target` (GL_ARRAY_BUFFER,
    /// GL_ELEMENT_ARRAY_BUFFER, GL_UNIFORM_BUFFER, ...). Needs a current context.
    explicit Buffer(GLenum target);
    ~Buffer();

    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;

    /// Replaces the contents with `bytes` bytes from `data` (glBufferData;
    /// `data` may be null to reserve). `usage`: GL_STATIC_DRAW for data set
    /// once, GL_DYNAMIC_DRAW or GL_STREAM_DRAW for data rewritten often.
    /// Uploads through GL_COPY_WRITE_BUFFER, so it never changes the index
    /// buffer of whatever vertex array happens to be bound.
    void upload(const void* data, std::size_t bytes, GLenum usage = GL_STATIC_DRAW);
    template <typename T>
    void upload(const std::vector<T>& values, GLenum usage = GL_STATIC_DRAW) {
        upload(values.data(), values.size() * sizeof(T), usage);
    }
    /// Overwrites `bytes` bytes at `offset` (glBufferSubData); the range must
    /// lie inside the last upload().
    void update(std::size_t offset, const void* data, std::size_t bytes);

    /// Binds to target(). An element buffer bound while a vertex array is bound
    /// becomes that vertex array's index buffer (use VertexArray::elementBuffer()).
    void bind() const;
    /// Binds to binding point `index` of target() (uniform buffers).
    void bindBase(GLuint index) const;

    GLenum target() const { return m_target; }
    std::size_t size() const { return m_size; } // bytes, as of the last upload()
    GLuint id() const { return m_id; }           // 0 when empty
    /// Gives up ownership: returns the id and leaves this Buffer empty.
    GLuint release();

private:
    GLenum m_target = 0;
    GLuint m_id = 0;
    std::size_t m_size = 0;
};

} // namespace stoa
