#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/StudentPass.hpp>
#include <stoa/render/ShadowRenderer.hpp>
#include <stoa/scene/Scene.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace stoa {

const char* toString(PcfMode mode) {
    switch (mode) {
    case PcfMode::Single: return "single";
    case PcfMode::TwoByTwo: return "2x2";
    case PcfMode::ThreeByThree: return "3x3";
    }
    return "?";
}

// After the student's pass (run by runStudentPass(), which refuses GL state set
// behind RenderState): the cache forgets the bindings it may have made directly
// (glUseProgram), and the app's target is bound again.
void ShadowRenderer::afterStudentPass(GLuint target) {
    StateCache& cache = StateCache::current();
    cache.forget();
    cache.bindFramebuffer(target);
    cache.useProgram(0);
}

ShadowRenderer::ShadowRenderer(const Program& depthProgram, const Program& shadowedProgram,
                               const Program& mapViewProgram)
    : m_depthProgram(depthProgram), m_shadowedProgram(shadowedProgram), m_mapViewProgram(mapViewProgram) {}

void ShadowRenderer::renderShadowMap(const Scene& scene, const ShadowLight& light, int mapSize) {
    STOA_ASSERT(mapSize > 0, "ShadowRenderer::renderShadowMap(): the map needs at least one texel per side");
    if (m_shadowMap.width() != mapSize) {
        FramebufferOptions options;
        options.color = false;
        options.depthTexture = true;
        m_shadowMap = Framebuffer(mapSize, mapSize, options);
    }
    // The lab draws into whatever the app bound (the window, or the headless
    // target): remember it (the StateCache knows it), since the depth pass binds the map.
    const GLuint previous = StateCache::current().drawFramebuffer();
    runStudentPass("renderShadowPass", [&] {
        studentCode().shadows.renderShadowPass(scene, m_shadowMap, m_depthProgram, light.lightSpaceMatrix);
    });
    afterStudentPass(previous);
}

void ShadowRenderer::renderLit(const Scene& scene, const Camera& camera, glm::ivec2 size, const ShadowLight& light,
                               const ShadowSettings& settings) {
    const bool withMap = settings.enabled && m_shadowMap.id() != 0;
    if (withMap) m_shadowMap.bindDepthTexture(kShadowMapUnit);
    m_shadowedProgram.set("uShadowMap", kShadowMapUnit);
    m_shadowedProgram.set("uShadowsEnabled", withMap);
    m_shadowedProgram.set("uLightKind", light.perspective ? 1 : 0);
    m_shadowedProgram.set("uLightSpaceMatrix", light.lightSpaceMatrix);
    m_shadowedProgram.set("uShadowBias", settings.bias);
    m_shadowedProgram.set("uPcfMode", static_cast<int>(settings.pcf));
    m_forward.clearColor = clearColor;
    m_forward.render(scene, camera, m_shadowedProgram, size);
}

void ShadowRenderer::render(const Scene& scene, const Camera& camera, glm::ivec2 size, const ShadowLight& light,
                            const ShadowSettings& settings) {
    if (settings.cascades.count > 0) {
        renderCascaded(scene, camera, size, light, settings);
        return;
    }
    if (settings.enabled || settings.showMap) renderShadowMap(scene, light, settings.mapSize);
    renderLit(scene, camera, size, light, settings);
    if (settings.showMap) {
        const int side = std::max(1, std::min(size.x, size.y) / 3);
        drawMapView(m_shadowMap, light, {size.x - side - 8, 8, side, side});
    }
}

void ShadowRenderer::drawMapView(const Framebuffer& map, const ShadowLight& light, const glm::ivec4& rectangle) {
    map.bindDepthTexture(kShadowMapUnit);
    m_mapViewProgram.set("uDepthMap", kShadowMapUnit);
    m_mapViewProgram.set("uPerspective", light.perspective);
    m_mapViewProgram.set("uNear", light.near);
    m_mapViewProgram.set("uFar", light.far);
    m_overlay.draw(m_mapViewProgram, rectangle);
}

void ShadowRenderer::renderCascaded(const Scene& scene, const Camera& camera, glm::ivec2 size,
                                    const ShadowLight& light, const ShadowSettings& settings) {
    const int count = settings.cascades.count;
    STOA_ASSERT(count >= 1 && count <= kMaxCascades, "ShadowRenderer::render(): CascadeSettings::count must be 0 to 4");
    STOA_ASSERT(m_cascadeProgram != nullptr,
                "ShadowRenderer::render(): cascades need setCascadeProgram() (shadows/shadowed.vert + cascaded.frag)");
    STOA_ASSERT(!light.perspective && !scene.directionalLights.empty(),
                "ShadowRenderer::render(): cascades are for the sun (scene.directionalLights[0]); use light = sun");
    const glm::vec3 sunDirection = scene.directionalLights.front().direction;
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    const float far = std::min(settings.cascades.far, camera.farPlane());
    m_cascades.split(camera, far, count, settings.cascades.lambda);

    const bool withMaps = settings.enabled || settings.showMap;
    const GLuint previous = StateCache::current().drawFramebuffer();
    for (int i = 0; i < count && withMaps; ++i) {
        Framebuffer& map =
            m_cascades.fit(i, camera, aspect, sunDirection, settings.mapSize, light.sceneMin, light.sceneMax);
        runStudentPass("renderShadowPass", [&] {
            studentCode().shadows.renderShadowPass(scene, map, m_depthProgram, m_cascades.matrix(i));
        });
    }
    afterStudentPass(previous);

    const Program& program = *m_cascadeProgram;
    m_cascades.setUniforms(program, kFirstCascadeUnit, settings.mapSize, far, settings.enabled);
    program.set("uCascadeCount", count);
    program.set("uShadowsEnabled", settings.enabled);
    program.set("uPcfMode", static_cast<int>(settings.pcf));
    program.set("uCascadeColors", settings.cascades.colors);
    m_forward.clearColor = clearColor;
    m_forward.render(scene, camera, program, size);

    if (settings.showMap) {
        // The cascades side by side along the bottom, near to far from the left.
        const int side = std::max(1, std::min(size.x / (count + 1), size.y / 3));
        for (int i = 0; i < count; ++i)
            drawMapView(m_cascades.map(i), light, {size.x - (count - i) * (side + 4) - 4, 8, side, side});
    }
}

} // namespace stoa
