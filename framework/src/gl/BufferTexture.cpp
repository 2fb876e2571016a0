#include <stoa/gl/BufferTexture.hpp>
#include <stoa/gl/Debug.hpp>

#include <utility>

namespace stoa {

BufferTexture::BufferTexture(GLenum internalFormat) : m_buffer(GL_TEXTURE_BUFFER), m_format(internalFormat) {
    STOA_GL_CALL(glGenTextures(1, &m_texture));
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    upload(zero, sizeof(zero));
}

BufferTexture::~BufferTexture() { destroy(); }

BufferTexture::BufferTexture(BufferTexture&& other) noexcept
    : m_buffer(std::move(other.m_buffer)), m_texture(std::exchange(other.m_texture, 0)), m_format(other.m_format) {}

BufferTexture& BufferTexture::operator=(BufferTexture&& other) noexcept {
    if (this != &other) {
        destroy();
        m_buffer = std::move(other.m_buffer);
        m_texture = std::exchange(other.m_texture, 0);
        m_format = other.m_format;
    }
    return *this;
}

void BufferTexture::destroy() {
    if (m_texture != 0) glDeleteTextures(1, &m_texture);
    m_texture = 0;
}

void BufferTexture::upload(const void* data, std::size_t bytes) {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (bytes == 0) {
        data = zero;
        bytes = sizeof(zero);
    }
    m_buffer.upload(data, bytes, GL_STREAM_DRAW);
    // Attaching again after glBufferData: some drivers keep the old storage otherwise.
    GLint previous = 0;
    STOA_GL_CALL(glGetIntegerv(GL_TEXTURE_BINDING_BUFFER, &previous));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_BUFFER, m_texture));
    STOA_GL_CALL(glTexBuffer(GL_TEXTURE_BUFFER, m_format, m_buffer.id()));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_BUFFER, static_cast<GLuint>(previous)));
}

void BufferTexture::bind(int unit) const {
    STOA_GL_CALL(glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit)));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_BUFFER, m_texture));
}

} // namespace stoa
