#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/render/AmbientOcclusion.hpp>
#include <stoa/render/AmbientOcclusionPass.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/render/FrameUniforms.hpp>

#include <stdexcept>
#include <string>

namespace stoa {

namespace {

constexpr int kNoiseUnit = 10;   // clear of the G-buffer's units (DeferredRenderer)
constexpr int kRawUnit = 11;

} // namespace

AmbientOcclusionPass::AmbientOcclusionPass(const Program& occlusionProgram, const Program& blurProgram)
    : m_occlusionProgram(occlusionProgram), m_blurProgram(blurProgram) {
    for (const Program* program : {&occlusionProgram, &blurProgram})
        program->bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
}

void AmbientOcclusionPass::setKernel(const std::vector<glm::vec3>& kernel, const std::vector<glm::vec3>& noise) {
    if (kernel.empty() || kernel.size() > static_cast<std::size_t>(kMaxKernelSize))
        throw std::invalid_argument("ssaoKernel() returned " + std::to_string(kernel.size()) + " samples; the shader takes 1 to " +
                                    std::to_string(kMaxKernelSize));
    if (noise.size() != 16)
        throw std::invalid_argument("ssaoNoise() returned " + std::to_string(noise.size()) + " vectors, not 16");
    m_kernel = kernel;
    TextureOptions options;
    options.mipmaps = false;
    options.linear = false;
    options.wrap = GL_REPEAT;
    m_noise = std::make_unique<Texture2D>(Texture2D::empty(4, 4, GL_RGB32F, options));
    m_noise->bind(kNoiseUnit);
    STOA_GL_CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 4));
    STOA_GL_CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGB, GL_FLOAT, noise.data()));
}

void AmbientOcclusionPass::prepareTargets(glm::ivec2 size) {
    if (m_raw && m_raw->width() == size.x && m_raw->height() == size.y) return;
    FramebufferOptions options;
    options.colorFormats = {GL_R8};
    options.depth = false;
    m_raw = std::make_unique<Framebuffer>(size.x, size.y, options);
    m_blurred = std::make_unique<Framebuffer>(size.x, size.y, options);
}

void AmbientOcclusionPass::occlusion(const DeferredRenderer& renderer, glm::ivec2 size, const OcclusionSettings& settings) {
    if (m_kernel.empty()) throw std::logic_error("AmbientOcclusionPass: setKernel() before render()");
    prepareTargets(size);
    beginPass(passInto(*m_raw, RenderState::overlay()));
    m_occlusionProgram.use();
    renderer.bindGBuffer(m_occlusionProgram);
    m_noise->bind(kNoiseUnit);
    m_occlusionProgram.set("uNoise", kNoiseUnit);
    m_occlusionProgram.set("uKernelSize", static_cast<int>(m_kernel.size()));
    m_occlusionProgram.set("uRadius", settings.radius);
    m_occlusionProgram.set("uBias", settings.bias);
    STOA_GL_CALL(glUniform3fv(m_occlusionProgram.uniformLocation("uKernel"), static_cast<GLsizei>(m_kernel.size()), &m_kernel[0].x));
    m_overlay.draw(m_occlusionProgram, {0, 0, size.x, size.y});
}

void AmbientOcclusionPass::blur() {
    beginPass(passInto(*m_blurred, RenderState::overlay()));
    m_blurProgram.use();
    m_raw->bindColorTexture(kRawUnit);
    m_blurProgram.set("uRawOcclusion", kRawUnit);
    m_overlay.draw(m_blurProgram, {0, 0, m_raw->width(), m_raw->height()});
}

void AmbientOcclusionPass::render(const DeferredRenderer& renderer, glm::ivec2 size, const OcclusionSettings& settings) {
    occlusion(renderer, size, settings);
    blur();
}

} // namespace stoa
