#pragma once
// An offscreen render target: colour textures plus depth, read back to an Image.
// Every headless frame is drawn into one; windows use them for shadow maps,
// G-buffers and picking.
//
//   Framebuffer target(640, 480);
//   PassDescription pass;                // RenderPass.hpp
//   pass.target = &target;               // binds it; the viewport is all of it
//   pass.clear.color = pass.clear.depth = true;
//   beginPass(pass);
//   ...draw...
//   Image frame = target.readColor();    // RGBA, top row first
//
// Attachments are textures held by shared pointers, so that two framebuffers
// can share one (a G-buffer's depth-stencil reused by the lighting pass):
//
//   FramebufferOptions lighting;
//   lighting.depthAttachment = gBuffer.depthAttachment();   // the same texture

#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Texture2D.hpp>

#include <memory>
#include <vector>

namespace stoa {

class Image;

/// What a Framebuffer holds. The defaults: one RGBA8 colour texture and a depth+stencil buffer.
struct FramebufferOptions {
    bool color = true;           // colour textures, one per colorFormats entry (attachments 0, 1, ...)
    bool depth = true;           // depth (24 bits) and stencil (8 bits), as a renderbuffer
    bool depthTexture = false;   // depth as a texture to sample instead (shadow maps; no stencil); implies depth
    bool depthStencilTexture = false;   // depth (24) and stencil (8) as one texture (GL_DEPTH24_STENCIL8)
                                        // that another framebuffer can share; implies depth
    std::vector<GLenum> colorFormats{GL_RGBA8}; // e.g. {GL_RGBA16F, GL_RGBA16F, GL_RGBA8} for a G-buffer,
                                                // {GL_R32UI} for picking IDs
    /// Existing textures to attach instead of making new ones: colour
    /// attachment i uses colorAttachments[i] when that entry is set (then
    /// colorFormats[i] is not used, but the count still is); the depth
    /// attachment uses depthAttachment when set (a depth or depth-stencil
    /// texture of the framebuffer's size, e.g. another's depthAttachment()).
    std::vector<std::shared_ptr<Texture2D>> colorAttachments;
    std::shared_ptr<Texture2D> depthAttachment;
};

class Framebuffer {
public:
    /// No framebuffer; no GL call.
    Framebuffer() = default;
    /// Creates the attachments (colour textures: clamped, linear unless integer;
    /// depth texture: clamped, nearest). Keeps the current framebuffer bound.
    /// Throws std::runtime_error naming the status (GL_FRAMEBUFFER_UNSUPPORTED, ...)
    /// when the driver rejects the combination.
    Framebuffer(int width, int height, const FramebufferOptions& options = {});
    ~Framebuffer();

    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;
    Framebuffer(Framebuffer&& other) noexcept;
    Framebuffer& operator=(Framebuffer&& other) noexcept;

    /// Binds for drawing and reading (no call when bound already); nothing
    /// else changes: the viewport is the pass's (beginPass() sets it).
    void bind() const;
    /// Binds the window's framebuffer (0).
    static void bindDefault();

    /// Colour attachment `attachment` as RGBA8, row 0 at the top (as Image
    /// keeps it). For normalised and float formats; integer ones: readPixels().
    Image readColor(int attachment = 0) const;
    /// Depth in [0, 1] (window depth), width() * height() values, top row first.
    std::vector<float> readDepth() const;
    /// glReadPixels of a rectangle of `attachment` (x, y from the bottom-left
    /// corner, rows bottom-up as GL gives them). `format`/`type` as for
    /// glReadPixels, e.g. GL_RED_INTEGER/GL_UNSIGNED_INT for a GL_R32UI target.
    void readPixels(int attachment, int x, int y, int width, int height, GLenum format, GLenum type,
                    void* out) const;

    /// The id of colour texture `attachment`; 0 when there is none.
    GLuint colorTexture(int attachment = 0) const;
    /// The id of the depth (or depth-stencil) texture; 0 when depth is a renderbuffer.
    GLuint depthTexture() const { return m_depthTexture ? m_depthTexture->id() : 0; }
    /// The attachments themselves, to share with another framebuffer or to sample.
    std::shared_ptr<Texture2D> depthAttachment() const { return m_depthTexture; }
    std::shared_ptr<Texture2D> colorAttachment(int attachment = 0) const;
    /// Binds colour texture `attachment` (or the depth texture) to texture unit `unit`.
    void bindColorTexture(int unit, int attachment = 0) const;
    void bindDepthTexture(int unit) const;

    int width() const { return m_width; }   // pixels
    int height() const { return m_height; } // pixels
    GLuint id() const { return m_id; }      // 0 when empty
    /// Gives up ownership of the framebuffer object (its attachments are still
    /// deleted with this object); returns the id.
    GLuint release();

private:
    void destroy();
    void bindForReading(int attachment) const;

    GLuint m_id = 0;
    GLuint m_depthRenderbuffer = 0;
    std::vector<std::shared_ptr<Texture2D>> m_colorTextures;
    std::shared_ptr<Texture2D> m_depthTexture;
    int m_width = 0;
    int m_height = 0;
};

} // namespace stoa
