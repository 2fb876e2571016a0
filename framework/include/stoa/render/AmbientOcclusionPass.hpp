#pragma once
// Lab 09's two passes over a G-buffer (DeferredRenderer::renderGeometry()):
// the occlusion estimate (shaders/ssao/ssao.frag, the student's ssao.glsl)
// into a one-channel target, then its 4 x 4 blur (shaders/ssao/blur.frag)
// into another. The blurred target is what DeferredSettings::ambientOcclusion
// takes. Lab 09's app and tests/benchmarks/ssao_benchmark.cpp draw through it.
//
// The kernel and the noise come from the student's ssaoKernel() and
// ssaoNoise() (lab 09's), handed over as data, so this file names
// no student function.
//
//   AmbientOcclusionPass ao(occlusionProgram, blurProgram);           // needs a current context
//   ao.setKernel(ssaoKernel(32, 1), ssaoNoise(2));
//   renderer.renderGeometry(items, camera, size);
//   ao.render(renderer, size, {1.0f, 0.025f});
//   settings.ambientOcclusion = &ao.blurred();

#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/render/TextureOverlay.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace stoa {

class DeferredRenderer;
class Program;

struct OcclusionSettings {
    float radius = 1.0f;    // the hemisphere's radius, view-space metres
    float bias = 0.025f;    // the depth comparison's bias, view-space metres
};

class AmbientOcclusionPass {
public:
    /// The programs basic/image.vert + ssao/ssao.frag and basic/image.vert +
    /// ssao/blur.frag; they must outlive the pass. Needs a current context.
    AmbientOcclusionPass(const Program& occlusionProgram, const Program& blurProgram);

    /// The kernel (1..kMaxKernelSize samples) and the 16 noise vectors, row by
    /// row; uploads the noise as a 4 x 4 repeating texture. Throws
    /// std::invalid_argument naming the function whose result has the wrong size.
    void setKernel(const std::vector<glm::vec3>& kernel, const std::vector<glm::vec3>& noise);
    bool hasKernel() const { return !m_kernel.empty(); }

    /// Both passes at `size` pixels over the G-buffer the renderer last drew;
    /// leaves the blurred target bound.
    void render(const DeferredRenderer& renderer, glm::ivec2 size, const OcclusionSettings& settings);
    /// The passes one at a time (for timing): render() is occlusion() then blur().
    void occlusion(const DeferredRenderer& renderer, glm::ivec2 size, const OcclusionSettings& settings);
    void blur();

    /// The targets of the last render(): one value per pixel in .r, 1 open, 0 hidden.
    const Texture2D& raw() const { return *m_raw->colorAttachment(0); }
    const Texture2D& blurred() const { return *m_blurred->colorAttachment(0); }
    const Framebuffer& rawTarget() const { return *m_raw; }
    const Framebuffer& blurredTarget() const { return *m_blurred; }

private:
    void prepareTargets(glm::ivec2 size);

    const Program& m_occlusionProgram;
    const Program& m_blurProgram;
    std::vector<glm::vec3> m_kernel;
    std::unique_ptr<Texture2D> m_noise;
    std::unique_ptr<Framebuffer> m_raw;
    std::unique_ptr<Framebuffer> m_blurred;
    TextureOverlay m_overlay;
};

} // namespace stoa
