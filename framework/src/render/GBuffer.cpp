#include <stoa/render/GBuffer.hpp>

namespace stoa {

namespace {

FramebufferOptions gBufferOptions() {
    FramebufferOptions options;
    options.colorFormats = {GL_RGBA8, GL_RG16};
    options.depthStencilTexture = true;
    return options;
}

} // namespace

GBuffer::GBuffer(int width, int height) : m_target(width, height, gBufferOptions()) {}

bool GBuffer::resize(glm::ivec2 size) {
    if (m_target.id() != 0 && size.x == m_target.width() && size.y == m_target.height()) return false;
    m_target = Framebuffer(size.x, size.y, gBufferOptions());
    return true;
}

void GBuffer::bindTextures(int firstUnit) const {
    m_target.bindColorTexture(firstUnit, kAlbedoSpecular);
    m_target.bindColorTexture(firstUnit + 1, kNormal);
    m_target.bindDepthTexture(firstUnit + 2);
}

std::size_t GBuffer::bytes() const {
    const std::size_t pixels = static_cast<std::size_t>(m_target.width()) * static_cast<std::size_t>(m_target.height());
    return pixels * (4 + 4 + 4);
}

} // namespace stoa
