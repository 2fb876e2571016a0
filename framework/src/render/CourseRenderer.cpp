#include <stoa/gl/Debug.hpp>
#include <stoa/render/CourseRenderer.hpp>

#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/geometry/Material.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <chrono>

namespace stoa {

namespace {

constexpr int kNormalMapUnit = MeshObject::kFirstFreeTextureUnit;   // beside the diffuse and specular maps
constexpr int kSkyUnit = 3;
constexpr int kFirstCascadeUnit = 12;   // 12..15: clear of the G-buffer's, the tiles' and the occlusion's
constexpr float kCascadeLambda = 0.75f;
constexpr int kOcclusionKernelSize = 32;   // samples of the student's SSAO kernel
constexpr float kShininess = 24.0f;     // DeferredSettings' default, for the sun as for the point lights

// Green, yellow, orange, red: level 0 (full detail) to 3, as lab 06's overview.
glm::vec3 levelTint(int level) {
    static const glm::vec3 tints[] = {{0.2f, 0.85f, 0.3f}, {0.95f, 0.9f, 0.2f}, {1.0f, 0.55f, 0.1f}, {0.95f, 0.2f, 0.15f}};
    return tints[std::min(std::max(level, 0), 3)];
}

double now() {
    using Clock = std::chrono::steady_clock;
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

} // namespace

const char* toString(CoursePass pass) {
    switch (pass) {
    case CoursePass::Culling: return "culling and LOD";
    case CoursePass::Shadows: return "cascaded shadows";
    case CoursePass::Geometry: return "G-buffer";
    case CoursePass::Occlusion: return "ambient occlusion";
    case CoursePass::Lighting: return "lights and sun";
    case CoursePass::Sky: return "skybox, sparks";
    case CoursePass::Present: return "present";
    case CoursePass::Count: break;
    }
    return "?";
}

const std::vector<std::string>& courseViewNames() {
    static const std::vector<std::string> names = {"final", "albedo",    "normals",  "positions", "specular",
                                                   "tiles", "occlusion", "cascades", "lod",       "trails",
                                                   "ids"};
    return names;
}

const char* toString(CourseView view) { return courseViewNames()[static_cast<std::size_t>(view)].c_str(); }

bool courseViewFromName(const std::string& name, CourseView& view) {
    const std::vector<std::string>& names = courseViewNames();
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) return false;
    view = static_cast<CourseView>(found - names.begin());
    return true;
}

CoursePrograms CoursePrograms::load(const Loader& load) {
    CoursePrograms programs;
    programs.deferred = DeferredPrograms::load(load);
    programs.geometry = &load("course/geometry.vert", "course/geometry.frag");
    programs.agents = &load("crowd/md2.vert", "course/agents.frag");
    programs.depth = &load("shadows/depth.vert", "shadows/depth.frag");
    programs.agentsDepth = &load("crowd/md2.vert", "crowd/depth.frag");
    programs.sun = &load("basic/image.vert", "course/sun.frag");
    programs.sky = &load("culling/skybox.vert", "culling/skybox.frag");
    programs.occlusion = &load("basic/image.vert", "ssao/ssao.frag");
    programs.blur = &load("basic/image.vert", "ssao/blur.frag");
    programs.grey = &load("basic/image.vert", "ssao/ao_view.frag");
    programs.ids = &load("picking/ids.vert", "picking/ids.frag");
    programs.idView = &load("basic/image.vert", "picking/id_view.frag");
    for (const Program* program : {programs.geometry, programs.agents, programs.agentsDepth, programs.sun, programs.sky,
                                   programs.ids})
        program->bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
    return programs;
}

CourseRenderer::CourseRenderer(const CoursePrograms& programs)
    : m_programs(programs),
      m_deferred(std::make_unique<DeferredRenderer>(programs.deferred)),
      m_occlusion(std::make_unique<AmbientOcclusionPass>(*programs.occlusion, *programs.blur)),
      m_sky(CubeMap::fromFolder(paths::assetsDir() / "sky")), m_skyCube(shapes::cube(2.0f)) {
    const OcclusionFunctions& occlusion = studentCode().occlusion;   // the student's samples, where handed over
    if (occlusion.ssaoKernel && occlusion.ssaoNoise)
        m_occlusion->setKernel(occlusion.ssaoKernel(kOcclusionKernelSize, 1), occlusion.ssaoNoise(2));
}

CourseRenderer::~CourseRenderer() = default;

void CourseRenderer::endPass(CoursePass pass, bool timed) {
    if (timed) STOA_GL_CALL(glFinish());
    const double end = now();
    m_stats.seconds[static_cast<std::size_t>(pass)] += end - m_passStart;
    m_passStart = end;
}

void CourseRenderer::render(const std::vector<CourseItem>& items, const CourseLighting& lighting, const Camera& camera,
                            glm::ivec2 size, const CourseSettings& settings, const CourseCrowd* crowd,
                            const GlowPass& glow) {
    const GLuint output = StateCache::current().drawFramebuffer();
    const bool timed = settings.timePasses;
    if (timed) STOA_GL_CALL(glFinish());   // what the caller drew before is not ours
    const double start = now();
    m_passStart = start;
    m_stats = CourseStats{};
    m_stats.pointLights = static_cast<int>(lighting.pointLights.size());
    m_view = camera.viewMatrix();

    cull(items, camera, size, settings);
    endPass(CoursePass::Culling, timed);

    renderCascades(items, lighting, camera, size, settings, crowd);
    endPass(CoursePass::Shadows, timed);

    renderGeometry(items, camera, size, settings, crowd);
    endPass(CoursePass::Geometry, timed);

    const bool occlusion = settings.ambientOcclusion && m_occlusion->hasKernel();
    if (occlusion) m_occlusion->render(*m_deferred, size, OcclusionSettings{});
    endPass(CoursePass::Occlusion, timed);

    // Ambient light and the point lights (lab 08's tiles), then in the light
    // buffer the sun with its shadows and the sky, then the picture.
    SceneLighting sceneLighting;
    sceneLighting.ambient = lighting.ambient;
    sceneLighting.moon = DirectionalLight{lighting.sunDirection, glm::vec3(0.0f)};   // the sun is drawSun()'s
    sceneLighting.sky = settings.sky ? glm::vec3(0.0f) : lighting.skyColor;
    DeferredSettings deferred;
    deferred.mode = LightingMode::Tiled;
    deferred.shininess = kShininess;
    deferred.reuseGBuffer = true;
    deferred.ambientOcclusion = occlusion ? &m_occlusion->blurred() : nullptr;
    switch (settings.view) {
    case CourseView::Albedo: deferred.view = DeferredView::Albedo; break;
    case CourseView::Normals: deferred.view = DeferredView::Normals; break;
    case CourseView::Positions: deferred.view = DeferredView::Positions; break;
    case CourseView::Specular: deferred.view = DeferredView::Specular; break;
    case CourseView::LightTiles: deferred.view = DeferredView::TileCounts; break;
    default: deferred.view = DeferredView::Final; break;
    }
    deferred.beforePresent = [&](const Framebuffer& lightBuffer) {
        drawSun(lighting, camera, settings);
        endPass(CoursePass::Lighting, timed);
        if (settings.sky) drawSky(lightBuffer);
        if (crowd && crowd->simulation && crowd->renderer && crowd->options.markers)
            drawMarkers(lightBuffer, lighting, camera, settings, *crowd);
        if (glow) glow(lightBuffer);
        endPass(CoursePass::Sky, timed);
    };
    StateCache::current().bindFramebuffer(output);
    m_deferred->render({}, lighting.pointLights, sceneLighting, camera, size, deferred);
    m_stats.tileListEntries = m_deferred->stats().tileListEntries;
    if (settings.view == CourseView::AmbientOcclusion) {
        StateCache::current().bindFramebuffer(output);
        beginPass(passInto(size, RenderState::overlay()));
        if (occlusion) {
            m_programs.grey->use();
            m_occlusion->blurred().bind(kSkyUnit);
            m_programs.grey->set("uImage", kSkyUnit);
            m_overlay.draw(*m_programs.grey, {0, 0, size.x, size.y});
        } else {
            STOA_GL_CALL(glClearColor(1.0f, 1.0f, 1.0f, 1.0f));   // no occlusion: everything fully open
            STOA_GL_CALL(glClear(GL_COLOR_BUFFER_BIT));
        }
    }
    if (settings.view == CourseView::Ids) drawIds(items, size, output);
    StateCache::current().bindFramebuffer(output);
    endPass(CoursePass::Present, timed);
    m_stats.totalSeconds = now() - start;
}

void CourseRenderer::cull(const std::vector<CourseItem>& items, const Camera& camera, glm::ivec2 size,
                          const CourseSettings& settings) {
    m_stats.objects = static_cast<int>(items.size());
    m_levels.assign(items.size(), 0);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    const glm::mat4 viewProjection = camera.projectionMatrix(aspect) * camera.viewMatrix();
    const CullingFunctions& culling = studentCode().culling;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const CourseItem& item = items[i];
        STOA_ASSERT(!item.levels.empty() && item.levels.front() != nullptr, "CourseItem: needs at least one level");
        const int levelCount = static_cast<int>(item.levels.size());
        int level = 0;
        if (settings.culling && item.sphere.radius > 0.0f) {
            if (culling.isVisible && !culling.isVisible(item.sphere, viewProjection)) {   // the student's
                m_levels[i] = -2;
                ++m_stats.culled;
                continue;
            }
            if (culling.levelOf) level = culling.levelOf(item.sphere, camera, size.y, levelCount);   // the student's
            if (level < 0) {
                m_levels[i] = -1;
                ++m_stats.tooSmall;
                continue;
            }
            level = std::min(level, levelCount - 1);
        }
        m_levels[i] = level;
        ++m_stats.perLevel[static_cast<std::size_t>(std::min(level, 3))];
    }
}

void CourseRenderer::renderCascades(const std::vector<CourseItem>& items, const CourseLighting& lighting,
                                    const Camera& camera, glm::ivec2 size, const CourseSettings& settings,
                                    const CourseCrowd* crowd) {
    m_cascades.clear();
    const ShadowFunctions& code = studentCode().shadows;
    const CullingFunctions& culling = studentCode().culling;
    if (!settings.shadows || !code.cascadeSplits || !code.frustumSliceCorners || !code.cascadeLightMatrix) return;
    const int count = std::min(std::max(settings.cascades, 1), ShadowCascades::kMaxCascades);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    const float far = std::min(settings.shadowFar, camera.farPlane());
    m_cascades.split(camera, far, count, kCascadeLambda);

    const GLuint previous = StateCache::current().drawFramebuffer();
    for (int i = 0; i < count; ++i) {
        Framebuffer& map = m_cascades.fit(i, camera, aspect, lighting.sunDirection, settings.shadowMapSize,
                                          lighting.sceneMin, lighting.sceneMax);
        const glm::mat4& matrix = m_cascades.matrix(i);
        PassDescription pass = passInto(map);
        pass.clear.depth = true;
        pass.state.cull = CullMode::None;   // open meshes (the floor, the wall's ends) cast from both sides
        beginPass(pass);
        const Program& depth = *m_programs.depth;
        depth.use();
        depth.set("uLightSpaceMatrix", matrix);
        for (std::size_t j = 0; j < items.size(); ++j) {
            const CourseItem& item = items[j];
            const bool cullable = settings.culling && item.sphere.radius > 0.0f;
            if (cullable && culling.isVisible && !culling.isVisible(item.sphere, matrix)) continue;   // not in this cascade
            // Seen by the camera: its level there; unseen (a shadow from outside the view): the coarsest.
            const int level = m_levels[j] >= 0 ? m_levels[j] : static_cast<int>(item.levels.size()) - 1;
            depth.set("uModel", item.model);
            item.levels[static_cast<std::size_t>(level)]->draw();
        }
        if (crowd && crowd->simulation && crowd->renderer) {
            FrameBlock block{};
            block.view = glm::mat4(1.0f);
            block.projection = matrix;
            m_lightFrame.update(block);
            m_lightFrame.bind();
            crowd->renderer->drawAgentsWith(*crowd->simulation, *m_programs.agentsDepth, crowd->options);
        }
    }
    StateCache::current().bindFramebuffer(previous);
}

void CourseRenderer::renderGeometry(const std::vector<CourseItem>& items, const Camera& camera, glm::ivec2 size,
                                    const CourseSettings& settings, const CourseCrowd* crowd) {
    // The deferred renderer's own geometry pass with nothing to draw: its
    // targets at this size, its frame block for this camera, the G-buffer
    // cleared and bound for the draws below.
    m_deferred->renderGeometry({}, camera, size);
    static const Material grey;
    const Program& program = *m_programs.geometry;
    program.use();
    program.set("uNormalMap", kNormalMapUnit);
    program.set("uDiffuseMap", MeshObject::kDiffuseMapUnit);
    const bool tinted = settings.view == CourseView::LevelsOfDetail;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (m_levels[i] < 0) continue;
        const CourseItem& item = items[i];
        const Material& material = item.material ? *item.material : grey;
        program.set("uModel", item.model);
        program.set("uNormalMatrix", item.normalMatrix);
        program.set("uMaterial.diffuse", material.diffuse);
        program.set("uMaterial.specular", material.specular);
        program.set("uHasDiffuseMap", item.diffuseMap != nullptr);
        if (item.diffuseMap) item.diffuseMap->bind(MeshObject::kDiffuseMapUnit);
        const bool bumped = settings.normalMaps && item.normalMap != nullptr;
        program.set("uHasNormalMap", bumped);
        if (bumped) item.normalMap->bind(kNormalMapUnit);
        const bool tintThis = tinted && item.sphere.radius > 0.0f;
        program.set("uTint", tintThis ? levelTint(m_levels[i]) : glm::vec3(1.0f));
        program.set("uTintAmount", tintThis ? 0.85f : 0.0f);
        item.levels[static_cast<std::size_t>(m_levels[i])]->draw();
    }
    if (crowd && crowd->simulation && crowd->renderer) {
        crowd->renderer->drawAgentsWith(*crowd->simulation, *m_programs.agents, crowd->options);
        m_stats.agents = static_cast<int>(std::count_if(crowd->simulation->agents().begin(),
                                                        crowd->simulation->agents().end(),
                                                        [](const CrowdAgent& agent) { return agent.alive; }));
    }
}

void CourseRenderer::drawSun(const CourseLighting& lighting, const Camera& camera, const CourseSettings& settings) {
    const bool cascadeView = settings.view == CourseView::Cascades;
    RenderState state = RenderState::overlay();
    state.blend = cascadeView ? BlendMode::Opaque : BlendMode::Additive;
    const glm::ivec2 size = m_deferred->gBuffer().size();
    const Program& program = *m_programs.sun;
    program.use();
    m_deferred->bindGBuffer(program);
    program.set("uInverseView", glm::inverse(m_view));
    program.set("uSunDirectionView", glm::normalize(glm::mat3(m_view) * lighting.sunDirection));
    program.set("uSunDirectionWorld", glm::normalize(lighting.sunDirection));
    program.set("uSunColor", lighting.sunColor);
    program.set("uShininess", kShininess);
    m_cascades.setUniforms(program, kFirstCascadeUnit, settings.shadowMapSize, camera.farPlane(), true);
    program.set("uCascadeCount", std::max(m_cascades.count(), 1));
    program.set("uShadowsEnabled", m_cascades.count() > 0);
    program.set("uPcfMode", static_cast<int>(settings.pcf));
    program.set("uCascadeColors", cascadeView);
    m_overlay.draw(program, {0, 0, size.x, size.y}, state);   // into the light buffer, bound by the caller
}

void CourseRenderer::drawMarkers(const Framebuffer& target, const CourseLighting& lighting, const Camera& camera,
                                 const CourseSettings& settings, const CourseCrowd& crowd) {
    const glm::ivec2 size = m_deferred->gBuffer().size();
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    Scene lights;
    lights.ambient = lighting.ambient;
    lights.directionalLights = {DirectionalLight{lighting.sunDirection, lighting.sunColor}};
    m_markerFrame.update(camera, aspect, lights);
    m_markerFrame.bind();
    RenderState state;
    state.cull = CullMode::None;
    beginPass(passInto(target, state));   // depth-tested against the G-buffer's copy
    CrowdView view;
    view.view = camera.viewMatrix();
    view.projection = camera.projectionMatrix(aspect);
    view.eye = camera.eyePosition();
    CrowdDrawOptions options = crowd.options;
    options.trails = options.trails || settings.view == CourseView::Trails;
    crowd.renderer->drawMarkersWith(*crowd.simulation, view, options);
}

// Lab 07's ID pass over the drawn items (each its CourseItem::id, packed by the
// student's packObjectId() into a GL_RGBA8UI target), shown in false colour.
void CourseRenderer::drawIds(const std::vector<CourseItem>& items, glm::ivec2 size, GLuint output) {
    if (!m_idTarget || m_idTarget->width() != size.x || m_idTarget->height() != size.y) {
        FramebufferOptions options;
        options.colorFormats = {GL_RGBA8UI};
        m_idTarget = std::make_unique<Framebuffer>(size.x, size.y, options);
    }
    PassDescription pass = passInto(*m_idTarget);
    pass.clear.depth = true;
    pass.state.cull = CullMode::None;
    beginPass(pass);
    const GLuint background[4] = {0, 0, 0, 0};
    STOA_GL_CALL(glClearBufferuiv(GL_COLOR, 0, background));   // an integer target clears with its own call
    const Program& ids = *m_programs.ids;
    ids.use();
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (m_levels[i] < 0) continue;
        ids.set("uModel", items[i].model);
        ids.set("uObjectId", items[i].id);
        items[i].levels[static_cast<std::size_t>(m_levels[i])]->draw();
    }
    StateCache::current().bindFramebuffer(output);
    const Program& view = *m_programs.idView;
    view.use();
    m_idTarget->bindColorTexture(kSkyUnit);
    view.set("uIds", kSkyUnit);
    m_overlay.draw(view, {0, 0, size.x, size.y});
}

void CourseRenderer::drawSky(const Framebuffer& target) {
    RenderState state;
    state.depth.func = GL_LEQUAL;   // at the far plane: only where the G-buffer's depth is still 1
    state.depth.write = false;
    state.cull = CullMode::None;
    beginPass(passInto(target, state));
    const Program& program = *m_programs.sky;
    program.use();
    m_sky.bind(kSkyUnit);
    program.set("uSky", kSkyUnit);
    m_skyCube.draw();
}

} // namespace stoa
