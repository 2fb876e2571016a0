#include <stoa/gl/Buffer.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/gl/Debug.hpp>

#include <utility>

namespace stoa {

Buffer::Buffer(GLenum target) : m_target(target) {
    STOA_GL_CALL(glGenBuffers(1, &m_id));
}

Buffer::~Buffer() {
    if (m_id) glDeleteBuffers(1, &m_id);
}

Buffer::Buffer(Buffer&& other) noexcept
    : m_target(other.m_target), m_id(std::exchange(other.m_id, 0)), m_size(std::exchange(other.m_size, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        if (m_id) glDeleteBuffers(1, &m_id);
        m_target = other.m_target;
        m_id = std::exchange(other.m_id, 0);
        m_size = std::exchange(other.m_size, 0);
    }
    return *this;
}

GLuint Buffer::release() {
    m_size = 0;
    return std::exchange(m_id, 0);
}

void Buffer::upload(const void* data, std::size_t bytes, GLenum usage) {
    STOA_ASSERT(m_id != 0, "Buffer::upload(): the buffer is empty (default-constructed, moved from or released). "
                           "Create it with Buffer(GL_ARRAY_BUFFER) or another target.");
    // Any target stores any data; GL_COPY_WRITE_BUFFER is bound to nothing a
    // draw call reads, unlike GL_ELEMENT_ARRAY_BUFFER (part of the bound VAO).
    STOA_GL_CALL(glBindBuffer(GL_COPY_WRITE_BUFFER, m_id));
    STOA_GL_CALL(glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), data, usage));
    STOA_GL_CALL(glBindBuffer(GL_COPY_WRITE_BUFFER, 0));
    m_size = bytes;
}

void Buffer::update(std::size_t offset, const void* data, std::size_t bytes) {
    STOA_ASSERT(m_id != 0, "Buffer::update(): the buffer is empty. Create it and upload() data first.");
    STOA_ASSERT(offset + bytes <= m_size, "Buffer::update(): the range runs past the end of the buffer. "
                                          "upload() enough bytes first, or update a smaller range.");
    STOA_GL_CALL(glBindBuffer(GL_COPY_WRITE_BUFFER, m_id));
    STOA_GL_CALL(glBufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset),
                                 static_cast<GLsizeiptr>(bytes), data));
    STOA_GL_CALL(glBindBuffer(GL_COPY_WRITE_BUFFER, 0));
}

void Buffer::bind() const {
    STOA_ASSERT(m_id != 0, "Buffer::bind(): the buffer is empty (default-constructed, moved from or released).");
    STOA_GL_CALL(glBindBuffer(m_target, m_id));
}

void Buffer::bindBase(GLuint index) const {
    STOA_ASSERT(m_id != 0, "Buffer::bindBase(): the buffer is empty (default-constructed, moved from or released).");
    STOA_GL_CALL(glBindBufferBase(m_target, index, m_id));
}

} // namespace stoa
