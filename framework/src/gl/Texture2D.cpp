#include <stoa/gl/Texture2D.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/image/Image.hpp>

#include <cstring>
#include <utility>
#include <vector>

namespace stoa {

namespace {

struct PixelFormat {
    GLenum internalFormat;
    GLenum format;
};

PixelFormat formatFor(int channels) {
    switch (channels) {
    case 1: return {GL_R8, GL_RED};
    case 2: return {GL_RG8, GL_RG};
    case 3: return {GL_RGB8, GL_RGB};
    default: return {GL_RGBA8, GL_RGBA};
    }
}

// The upload format glTexImage2D needs for storage without data.
PixelFormat transferFormatFor(GLenum internalFormat) {
    switch (internalFormat) {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F: return {internalFormat, GL_DEPTH_COMPONENT};
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH32F_STENCIL8: return {internalFormat, GL_DEPTH_STENCIL};
    case GL_R8UI: case GL_R16UI: case GL_R32UI:
    case GL_R8I: case GL_R16I: case GL_R32I: return {internalFormat, GL_RED_INTEGER};
    case GL_RG8UI: case GL_RG16UI: case GL_RG32UI:
    case GL_RG8I: case GL_RG16I: case GL_RG32I: return {internalFormat, GL_RG_INTEGER};
    case GL_RGBA8UI: case GL_RGBA16UI: case GL_RGBA32UI:
    case GL_RGBA8I: case GL_RGBA16I: case GL_RGBA32I: return {internalFormat, GL_RGBA_INTEGER};
    default: return {internalFormat, GL_RGBA};
    }
}

// The type that goes with it (the spec's table 3.2 pairs each integer format
// with the type of its size and sign).
GLenum transferTypeFor(GLenum internalFormat, GLenum format) {
    if (format == GL_DEPTH_STENCIL) return GL_UNSIGNED_INT_24_8;
    if (format == GL_DEPTH_COMPONENT) return GL_FLOAT;
    switch (internalFormat) {
    case GL_R8UI: case GL_RG8UI: case GL_RGBA8UI: return GL_UNSIGNED_BYTE;
    case GL_R8I: case GL_RG8I: case GL_RGBA8I: return GL_BYTE;
    case GL_R16UI: case GL_RG16UI: case GL_RGBA16UI: return GL_UNSIGNED_SHORT;
    case GL_R16I: case GL_RG16I: case GL_RGBA16I: return GL_SHORT;
    case GL_R32I: case GL_RG32I: case GL_RGBA32I: return GL_INT;
    default: break;
    }
    if (format == GL_RED_INTEGER || format == GL_RG_INTEGER || format == GL_RGBA_INTEGER) return GL_UNSIGNED_INT;
    return GL_UNSIGNED_BYTE;
}

// Creating a texture has to bind it; this puts back what the active unit had,
// so that making a texture never unbinds one a caller bound a moment before
// (a normal map on unit 2, then a diffuse map loaded at its first draw).
class KeepTextureBinding {
public:
    KeepTextureBinding() { glGetIntegerv(GL_TEXTURE_BINDING_2D, &m_previous); }
    ~KeepTextureBinding() { glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(m_previous)); }
    KeepTextureBinding(const KeepTextureBinding&) = delete;
    KeepTextureBinding& operator=(const KeepTextureBinding&) = delete;

private:
    GLint m_previous = 0;
};

} // namespace

void Texture2D::create(int width, int height, GLenum internalFormat) {
    m_width = width;
    m_height = height;
    m_internalFormat = internalFormat;
    STOA_GL_CALL(glGenTextures(1, &m_id));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_2D, m_id));
}

void Texture2D::applyOptions(const TextureOptions& options, bool hasMipmaps) const {
    GLenum minFilter = options.linear ? GL_LINEAR : GL_NEAREST;
    if (hasMipmaps) minFilter = options.linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST;
    STOA_GL_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter)));
    STOA_GL_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, options.linear ? GL_LINEAR : GL_NEAREST));
    STOA_GL_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(options.wrap)));
    STOA_GL_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(options.wrap)));
}

Texture2D Texture2D::fromImage(const Image& image, const TextureOptions& options) {
    STOA_ASSERT(!image.empty(), "Texture2D::fromImage(): the image is empty. Load it first (Image::load) "
                                "or use Texture2D::empty() for a render target.");
    const PixelFormat format = formatFor(image.channels());

    // Image rows run top-down, GL's bottom-up: upload the last row first so
    // that v = 0 lies at the image's bottom edge.
    const std::size_t rowBytes = static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.channels());
    std::vector<std::uint8_t> bottomUp(image.sizeInBytes());
    for (int row = 0; row < image.height(); ++row)
        std::memcpy(bottomUp.data() + rowBytes * static_cast<std::size_t>(image.height() - 1 - row),
                    image.data() + rowBytes * static_cast<std::size_t>(row), rowBytes);

    const KeepTextureBinding keep;
    Texture2D texture;
    texture.create(image.width(), image.height(), format.internalFormat);
    STOA_GL_CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 1)); // rows of 3-channel images are not 4-byte aligned
    STOA_GL_CALL(glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(format.internalFormat), image.width(),
                              image.height(), 0, format.format, GL_UNSIGNED_BYTE, bottomUp.data()));
    STOA_GL_CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 4));
    if (image.channels() <= 2) {
        // Grey images read as grey: r into r, g and b; alpha from g (or 1).
        const GLint alpha = image.channels() == 2 ? GL_GREEN : GL_ONE;
        const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, alpha};
        STOA_GL_CALL(glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle));
    }
    if (options.mipmaps) STOA_GL_CALL(glGenerateMipmap(GL_TEXTURE_2D));
    texture.applyOptions(options, options.mipmaps);
    return texture;
}

Texture2D Texture2D::fromFile(const std::filesystem::path& path, const TextureOptions& options) {
    return fromImage(Image::load(path), options);
}

Texture2D Texture2D::empty(int width, int height, GLenum internalFormat, const TextureOptions& options) {
    STOA_ASSERT(width > 0 && height > 0, "Texture2D::empty(): width and height must be positive.");
    const PixelFormat format = transferFormatFor(internalFormat);
    const KeepTextureBinding keep;
    Texture2D texture;
    texture.create(width, height, internalFormat);
    STOA_GL_CALL(glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format.format,
                              transferTypeFor(internalFormat, format.format), nullptr));
    texture.applyOptions(options, false);
    return texture;
}

Texture2D::~Texture2D() {
    if (m_id) glDeleteTextures(1, &m_id);
}

Texture2D::Texture2D(Texture2D&& other) noexcept
    : m_id(std::exchange(other.m_id, 0)),
      m_width(other.m_width),
      m_height(other.m_height),
      m_internalFormat(other.m_internalFormat) {}

Texture2D& Texture2D::operator=(Texture2D&& other) noexcept {
    if (this != &other) {
        if (m_id) glDeleteTextures(1, &m_id);
        m_id = std::exchange(other.m_id, 0);
        m_width = other.m_width;
        m_height = other.m_height;
        m_internalFormat = other.m_internalFormat;
    }
    return *this;
}

GLuint Texture2D::release() { return std::exchange(m_id, 0); }

void Texture2D::bind(int unit) const {
    STOA_ASSERT(m_id != 0, "Texture2D::bind(): the texture is empty (default-constructed, moved from or released). "
                           "Create it with Texture2D::fromFile() or fromImage().");
    STOA_ASSERT(unit >= 0 && unit < 16, "Texture2D::bind(): the unit must be 0..15 (OpenGL 3.3 guarantees 16).");
    STOA_GL_CALL(glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit)));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_2D, m_id));
}

} // namespace stoa
