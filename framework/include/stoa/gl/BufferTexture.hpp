#pragma once
// A buffer that shaders read as a one-dimensional array through texelFetch()
// (a GL buffer texture): per-light data and per-tile light lists of any
// length, where a uniform array would be capped at a few hundred entries.
//
//   BufferTexture lights(GL_RGBA32F);
//   lights.upload(vec4s);                 // std::vector<glm::vec4>
//   lights.bind(3);                       // GLSL: uniform samplerBuffer uLights; texelFetch(uLights, i)
//
// GL_R32I data is read with an isamplerBuffer.

#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/OpenGL.hpp>

#include <cstddef>
#include <vector>

namespace stoa {

class BufferTexture {
public:
    /// No buffer; no GL call.
    BufferTexture() = default;
    /// An empty buffer read as `internalFormat` (GL_RGBA32F, GL_R32I, ...). Needs a current context.
    explicit BufferTexture(GLenum internalFormat);
    ~BufferTexture();

    BufferTexture(const BufferTexture&) = delete;
    BufferTexture& operator=(const BufferTexture&) = delete;
    BufferTexture(BufferTexture&& other) noexcept;
    BufferTexture& operator=(BufferTexture&& other) noexcept;

    /// Replaces the contents (GL_STREAM_DRAW: rewritten every frame). An
    /// empty upload keeps one zero texel, so that the texture stays complete.
    void upload(const void* data, std::size_t bytes);
    template <typename T>
    void upload(const std::vector<T>& values) {
        upload(values.data(), values.size() * sizeof(T));
    }

    /// Binds the texture to unit `unit` (GL_TEXTURE_BUFFER).
    void bind(int unit) const;

    GLuint textureId() const { return m_texture; }

private:
    void destroy();

    Buffer m_buffer;
    GLuint m_texture = 0;
    GLenum m_format = GL_RGBA32F;
};

} // namespace stoa
