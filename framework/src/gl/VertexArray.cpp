#include <stoa/gl/VertexArray.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/gl/Debug.hpp>

#include <utility>

namespace stoa {

namespace {
// Vertex attribute offsets are passed as pointers for historical reasons.
const void* asPointer(std::size_t offset) { return reinterpret_cast<const void*>(offset); }
} // namespace

VertexArray::VertexArray() {
    STOA_GL_CALL(glGenVertexArrays(1, &m_id));
}

VertexArray::~VertexArray() {
    if (m_id) glDeleteVertexArrays(1, &m_id);
}

VertexArray::VertexArray(VertexArray&& other) noexcept : m_id(std::exchange(other.m_id, 0)) {}

VertexArray& VertexArray::operator=(VertexArray&& other) noexcept {
    if (this != &other) {
        if (m_id) glDeleteVertexArrays(1, &m_id);
        m_id = std::exchange(other.m_id, 0);
    }
    return *this;
}

GLuint VertexArray::release() { return std::exchange(m_id, 0); }

void VertexArray::bind() const {
    STOA_ASSERT(m_id != 0, "VertexArray::bind(): the vertex array was moved from or released. "
                           "Keep the VertexArray (or the GpuMesh holding it) alive while you draw with it.");
    STOA_GL_CALL(glBindVertexArray(m_id));
}

void VertexArray::unbind() { STOA_GL_CALL(glBindVertexArray(0)); }

void VertexArray::attribute(GLuint location, const Buffer& buffer, int components, GLenum type, std::size_t stride,
                            std::size_t offset, bool normalized) {
    STOA_ASSERT(components >= 1 && components <= 4, "VertexArray::attribute(): components must be 1, 2, 3 or 4.");
    bind();
    STOA_GL_CALL(glBindBuffer(GL_ARRAY_BUFFER, buffer.id()));
    STOA_GL_CALL(glVertexAttribPointer(location, components, type, normalized ? GL_TRUE : GL_FALSE,
                                       static_cast<GLsizei>(stride), asPointer(offset)));
    STOA_GL_CALL(glEnableVertexAttribArray(location));
}

void VertexArray::integerAttribute(GLuint location, const Buffer& buffer, int components, GLenum type,
                                   std::size_t stride, std::size_t offset) {
    STOA_ASSERT(components >= 1 && components <= 4,
                "VertexArray::integerAttribute(): components must be 1, 2, 3 or 4.");
    bind();
    STOA_GL_CALL(glBindBuffer(GL_ARRAY_BUFFER, buffer.id()));
    STOA_GL_CALL(glVertexAttribIPointer(location, components, type, static_cast<GLsizei>(stride), asPointer(offset)));
    STOA_GL_CALL(glEnableVertexAttribArray(location));
}

void VertexArray::divisor(GLuint location, GLuint divisor) {
    bind();
    STOA_GL_CALL(glVertexAttribDivisor(location, divisor));
}

void VertexArray::elementBuffer(const Buffer& buffer) {
    bind();
    STOA_GL_CALL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id()));
}

} // namespace stoa
