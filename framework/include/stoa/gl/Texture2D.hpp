#pragma once
// A 2D texture, from an Image or a file, or empty for rendering into.
//
//   Texture2D albedo = Texture2D::fromFile(assets / "brick.png");
//   albedo.bind(0);
//   program.set("uAlbedo", 0);          // the sampler reads texture unit 0
//
// Texture coordinates follow OpenGL: uv (0,0) is the image's bottom-left
// corner, (1,1) its top-right (the rows are flipped on upload, as Image keeps
// row 0 at the top).

#include <stoa/gl/OpenGL.hpp>

#include <filesystem>

namespace stoa {

class Image;

/// How a texture is sampled. The defaults suit colour maps on meshes.
struct TextureOptions {
    bool mipmaps = true;    // build the mipmap chain (and sample it when minified)
    GLenum wrap = GL_REPEAT; // GL_REPEAT, GL_CLAMP_TO_EDGE or GL_MIRRORED_REPEAT, for s and t
    bool linear = true;     // bilinear (trilinear with mipmaps); false: nearest texel
};

class Texture2D {
public:
    /// No texture; no GL call.
    Texture2D() = default;

    /// Uploads `image`: 1 channel -> GL_R8 sampled as grey (r = g = b, a = 1),
    /// 2 -> GL_RG8 sampled as grey and alpha, 3 -> GL_RGB8, 4 -> GL_RGBA8.
    /// Asserts that the image is not empty. Like every creation function here,
    /// it leaves every texture unit's binding as it found it: bind() the new
    /// texture to use it.
    static Texture2D fromImage(const Image& image, const TextureOptions& options = {});
    /// Image::load(path) then fromImage(); InputError when the file is missing or does not decode.
    static Texture2D fromFile(const std::filesystem::path& path, const TextureOptions& options = {});
    /// Storage without contents, `internalFormat` e.g. GL_RGBA8, GL_RGBA16F,
    /// GL_R32UI, GL_DEPTH_COMPONENT24 (what a Framebuffer renders into).
    /// No mipmaps; options.mipmaps is ignored.
    static Texture2D empty(int width, int height, GLenum internalFormat, const TextureOptions& options = {});

    ~Texture2D();
    Texture2D(const Texture2D&) = delete;
    Texture2D& operator=(const Texture2D&) = delete;
    Texture2D(Texture2D&& other) noexcept;
    Texture2D& operator=(Texture2D&& other) noexcept;

    /// Binds to texture unit `unit` (0 = GL_TEXTURE0); leaves that unit active.
    void bind(int unit) const;

    int width() const { return m_width; }   // texels
    int height() const { return m_height; } // texels
    GLenum internalFormat() const { return m_internalFormat; }
    GLuint id() const { return m_id; } // 0 when empty
    /// Gives up ownership: returns the id and leaves this Texture2D empty.
    GLuint release();

private:
    void create(int width, int height, GLenum internalFormat);
    void applyOptions(const TextureOptions& options, bool hasMipmaps) const;

    GLuint m_id = 0;
    int m_width = 0;
    int m_height = 0;
    GLenum m_internalFormat = 0;
};

} // namespace stoa
