#include <stoa/gl/Framebuffer.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/image/Image.hpp>

#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace stoa {

namespace {

const char* statusName(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: return "an unknown framebuffer status";
    }
}

bool isIntegerFormat(GLenum format) {
    switch (format) {
    case GL_R8UI: case GL_R16UI: case GL_R32UI: case GL_R8I: case GL_R16I: case GL_R32I:
    case GL_RG8UI: case GL_RG16UI: case GL_RG32UI: case GL_RG8I: case GL_RG16I: case GL_RG32I:
    case GL_RGBA8UI: case GL_RGBA16UI: case GL_RGBA32UI: case GL_RGBA8I: case GL_RGBA16I: case GL_RGBA32I:
        return true;
    default:
        return false;
    }
}

bool isDepthFormat(GLenum format) {
    switch (format) {
    case GL_DEPTH_COMPONENT16: case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32: case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH24_STENCIL8: case GL_DEPTH32F_STENCIL8:
        return true;
    default:
        return false;
    }
}

bool hasStencil(GLenum format) { return format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8; }

} // namespace

Framebuffer::Framebuffer(int width, int height, const FramebufferOptions& options)
    : m_width(width), m_height(height) {
    STOA_ASSERT(width > 0 && height > 0, "Framebuffer(): width and height must be positive.");
    STOA_ASSERT(!options.color || !options.colorFormats.empty(),
                "Framebuffer(): options.color is set but options.colorFormats is empty. Name at least one format.");
    StateCache& cache = StateCache::current();
    const GLuint previousDraw = cache.drawFramebuffer();
    const GLuint previousRead = cache.readFramebuffer();

    STOA_GL_CALL(glGenFramebuffers(1, &m_id));
    STOA_GL_CALL(glBindFramebuffer(GL_FRAMEBUFFER, m_id));

    auto checkShared = [&](const Texture2D& texture, const char* what) {
        STOA_ASSERT(texture.id() != 0, "Framebuffer(): a shared attachment is an empty texture");
        if (texture.width() != width || texture.height() != height)
            throw std::runtime_error("Framebuffer(" + std::to_string(width) + "x" + std::to_string(height) +
                                     "): the shared " + what + " texture is " + std::to_string(texture.width()) +
                                     "x" + std::to_string(texture.height()) + "; attachments must match in size");
    };

    std::vector<GLenum> drawBuffers;
    if (options.color) {
        for (std::size_t i = 0; i < options.colorFormats.size(); ++i) {
            const GLenum format = options.colorFormats[i];
            const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(m_colorTextures.size());
            if (i < options.colorAttachments.size() && options.colorAttachments[i]) {
                checkShared(*options.colorAttachments[i], "colour");
                m_colorTextures.push_back(options.colorAttachments[i]);
            } else {
                TextureOptions sampling{/*mipmaps=*/false, GL_CLAMP_TO_EDGE, /*linear=*/!isIntegerFormat(format)};
                m_colorTextures.push_back(
                    std::make_shared<Texture2D>(Texture2D::empty(width, height, format, sampling)));
            }
            STOA_GL_CALL(glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D,
                                                m_colorTextures.back()->id(), 0));
            drawBuffers.push_back(attachment);
        }
        STOA_GL_CALL(glDrawBuffers(static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data()));
        STOA_GL_CALL(glReadBuffer(GL_COLOR_ATTACHMENT0));
    } else {
        // Depth only (a shadow map): without this the framebuffer is incomplete in GL 3.3.
        STOA_GL_CALL(glDrawBuffer(GL_NONE));
        STOA_GL_CALL(glReadBuffer(GL_NONE));
    }

    if (options.depthAttachment || options.depthTexture || options.depthStencilTexture) {
        if (options.depthAttachment) {
            checkShared(*options.depthAttachment, "depth");
            STOA_ASSERT(isDepthFormat(options.depthAttachment->internalFormat()),
                        "Framebuffer(): options.depthAttachment is not a depth texture. Share another "
                        "framebuffer's depthAttachment(), or make one with Texture2D::empty(w, h, GL_DEPTH24_STENCIL8).");
            m_depthTexture = options.depthAttachment;
        } else {
            const GLenum format = options.depthStencilTexture ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
            m_depthTexture = std::make_shared<Texture2D>(Texture2D::empty(
                width, height, format, TextureOptions{/*mipmaps=*/false, GL_CLAMP_TO_EDGE, /*linear=*/false}));
        }
        const GLenum attachment =
            hasStencil(m_depthTexture->internalFormat()) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
        STOA_GL_CALL(glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, m_depthTexture->id(), 0));
    } else if (options.depth) {
        STOA_GL_CALL(glGenRenderbuffers(1, &m_depthRenderbuffer));
        STOA_GL_CALL(glBindRenderbuffer(GL_RENDERBUFFER, m_depthRenderbuffer));
        STOA_GL_CALL(glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height));
        STOA_GL_CALL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                               m_depthRenderbuffer));
        STOA_GL_CALL(glBindRenderbuffer(GL_RENDERBUFFER, 0));
    }

    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    STOA_GL_CALL(glBindFramebuffer(GL_DRAW_FRAMEBUFFER, previousDraw));
    STOA_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, previousRead));
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        destroy();
        throw std::runtime_error("Framebuffer(" + std::to_string(width) + "x" + std::to_string(height) +
                                 "): the driver reports the framebuffer incomplete (" + statusName(status) +
                                 "). Try other colour formats or depth options.");
    }
}

void Framebuffer::destroy() {
    if (m_depthRenderbuffer) glDeleteRenderbuffers(1, &m_depthRenderbuffer);
    if (m_id) {
        StateCache::current().framebufferDeleted(m_id);
        glDeleteFramebuffers(1, &m_id);
    }
    m_depthRenderbuffer = 0;
    m_id = 0;
    m_colorTextures.clear();
    m_depthTexture.reset();
}

Framebuffer::~Framebuffer() { destroy(); }

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : m_id(std::exchange(other.m_id, 0)),
      m_depthRenderbuffer(std::exchange(other.m_depthRenderbuffer, 0)),
      m_colorTextures(std::move(other.m_colorTextures)),
      m_depthTexture(std::move(other.m_depthTexture)),
      m_width(other.m_width),
      m_height(other.m_height) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
    if (this != &other) {
        destroy();
        m_id = std::exchange(other.m_id, 0);
        m_depthRenderbuffer = std::exchange(other.m_depthRenderbuffer, 0);
        m_colorTextures = std::move(other.m_colorTextures);
        m_depthTexture = std::move(other.m_depthTexture);
        m_width = other.m_width;
        m_height = other.m_height;
    }
    return *this;
}

GLuint Framebuffer::release() { return std::exchange(m_id, 0); }

void Framebuffer::bind() const {
    STOA_ASSERT(m_id != 0, "Framebuffer::bind(): the framebuffer is empty (default-constructed, moved from or "
                           "released). Create it with Framebuffer(width, height).");
    StateCache::current().bindFramebuffer(m_id);
}

void Framebuffer::bindDefault() { StateCache::current().bindFramebuffer(0); }

void Framebuffer::bindForReading(int attachment) const {
    StateCache::current().bindReadFramebuffer(m_id);
    if (attachment >= 0) STOA_GL_CALL(glReadBuffer(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(attachment)));
}

void Framebuffer::readPixels(int attachment, int x, int y, int width, int height, GLenum format, GLenum type,
                             void* out) const {
    STOA_ASSERT(m_id != 0, "Framebuffer::readPixels(): the framebuffer is empty.");
    const bool depthRead = format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL || format == GL_STENCIL_INDEX;
    STOA_ASSERT(depthRead || (attachment >= 0 && attachment < static_cast<int>(m_colorTextures.size())),
                "Framebuffer::readPixels(): no such colour attachment. Count the entries of options.colorFormats.");
    STOA_ASSERT(x >= 0 && y >= 0 && x + width <= m_width && y + height <= m_height,
                "Framebuffer::readPixels(): the rectangle lies outside the framebuffer.");
    const GLuint previous = StateCache::current().readFramebuffer();
    bindForReading(depthRead ? -1 : attachment);
    STOA_GL_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
    STOA_GL_CALL(glReadPixels(x, y, width, height, format, type, out));
    STOA_GL_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 4));
    if (!depthRead && !m_colorTextures.empty()) STOA_GL_CALL(glReadBuffer(GL_COLOR_ATTACHMENT0));
    StateCache::current().bindReadFramebuffer(previous);
}

Image Framebuffer::readColor(int attachment) const {
    Image image(m_width, m_height, 4);
    readPixels(attachment, 0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
    image.flipVertically(); // GL hands rows bottom-up; Image keeps row 0 at the top
    return image;
}

std::vector<float> Framebuffer::readDepth() const {
    STOA_ASSERT(m_depthRenderbuffer || m_depthTexture,
                "Framebuffer::readDepth(): this framebuffer has no depth. Create it with options.depth = true.");
    std::vector<float> bottomUp(static_cast<std::size_t>(m_width) * static_cast<std::size_t>(m_height));
    readPixels(-1, 0, 0, m_width, m_height, GL_DEPTH_COMPONENT, GL_FLOAT, bottomUp.data());
    std::vector<float> topDown(bottomUp.size());
    const std::size_t row = static_cast<std::size_t>(m_width);
    for (int y = 0; y < m_height; ++y)
        std::memcpy(topDown.data() + row * static_cast<std::size_t>(m_height - 1 - y),
                    bottomUp.data() + row * static_cast<std::size_t>(y), row * sizeof(float));
    return topDown;
}

GLuint Framebuffer::colorTexture(int attachment) const {
    if (attachment < 0 || attachment >= static_cast<int>(m_colorTextures.size())) return 0;
    return m_colorTextures[static_cast<std::size_t>(attachment)]->id();
}

std::shared_ptr<Texture2D> Framebuffer::colorAttachment(int attachment) const {
    if (attachment < 0 || attachment >= static_cast<int>(m_colorTextures.size())) return nullptr;
    return m_colorTextures[static_cast<std::size_t>(attachment)];
}

void Framebuffer::bindColorTexture(int unit, int attachment) const {
    STOA_ASSERT(attachment >= 0 && attachment < static_cast<int>(m_colorTextures.size()),
                "Framebuffer::bindColorTexture(): no such colour attachment. Count options.colorFormats.");
    m_colorTextures[static_cast<std::size_t>(attachment)]->bind(unit);
}

void Framebuffer::bindDepthTexture(int unit) const {
    STOA_ASSERT(m_depthTexture != nullptr, "Framebuffer::bindDepthTexture(): no depth texture. "
                                           "Create the framebuffer with options.depthTexture = true.");
    m_depthTexture->bind(unit);
}

} // namespace stoa
