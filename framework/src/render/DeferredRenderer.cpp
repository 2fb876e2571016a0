#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/scene/ObjectUniforms.hpp>
#include <stoa/scene/Scene.hpp>

#include "TileDepthRanges.hpp"
#include "TileLightBinner.hpp"   // its code only where STOA_FRAMEWORK_TILE_LISTS (framework/src/render/CMakeLists.txt)

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

namespace {

// Texture units of the lighting passes, clear of the materials' (0, 1).
constexpr int kGBufferUnit = 2;            // 2, 3, 4: albedo/specular, normal, depth
constexpr int kLightsUnit = 5;
constexpr int kTileOffsetsUnit = 6;
constexpr int kTileLightsUnit = 7;
constexpr int kImageUnit = 8;
constexpr int kAmbientOcclusionUnit = 9;

constexpr int kSphereSlices = 16;
constexpr int kSphereStacks = 8;

// views.frag's modes.
enum ViewMode { kPresent = 0, kAlbedo = 1, kNormals = 2, kPositions = 3, kSpecular = 4, kHeat = 5 };

} // namespace

DeferredPrograms DeferredPrograms::load(
    const std::function<const Program&(const std::string&, const std::string&)>& load) {
    DeferredPrograms programs;
    programs.geometry = &load("deferred/geometry.vert", "deferred/geometry.frag");
    programs.forward = &load("deferred/forward.vert", "deferred/forward.frag");
    programs.ambient = &load("basic/image.vert", "deferred/ambient.frag");
    programs.lightVolume = &load("deferred/light_volume.vert", "deferred/light_volume.frag");
    programs.tiled = &load("basic/image.vert", "deferred/tiled.frag");
    programs.views = &load("basic/image.vert", "deferred/views.frag");
    return programs;
}

const char* toString(LightingMode mode) {
    switch (mode) {
    case LightingMode::Forward: return "forward";
    case LightingMode::Volumes: return "volumes";
    case LightingMode::Tiled: return "tiled";
    }
    return "?";
}

const char* toString(DeferredView view) {
    switch (view) {
    case DeferredView::Final: return "final";
    case DeferredView::Albedo: return "albedo";
    case DeferredView::Normals: return "normals";
    case DeferredView::Positions: return "positions";
    case DeferredView::Specular: return "specular";
    case DeferredView::Overdraw: return "overdraw";
    case DeferredView::TileCounts: return "tiles";
    }
    return "?";
}

DeferredRenderer::DeferredRenderer(const DeferredPrograms& programs)
    : m_programs(programs),
      m_sphere(shapes::sphere(1.0f, kSphereSlices, kSphereStacks)),
      m_lightTexels(GL_RGBA32F),
      m_tileOffsets(GL_R32I),
      m_tileLights(GL_R32I),
      m_depthRanges(std::make_unique<TileDepthRanges>()) {
#if STOA_FRAMEWORK_TILE_LISTS
    m_binner = std::make_unique<TileLightBinner>();
#endif
    for (const Program* program : {programs.geometry, programs.forward, programs.ambient, programs.lightVolume,
                                   programs.tiled, programs.views}) {
        STOA_ASSERT(program != nullptr, "DeferredRenderer: every program of DeferredPrograms must be set");
        program->bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
    }
    m_geometryUniforms = std::make_unique<ObjectUniforms>(*programs.geometry);
    m_forwardUniforms = std::make_unique<ObjectUniforms>(*programs.forward);
    // The mesh's faces lie inside the sphere through its vertices: the nearest
    // point of a face is at about cos(pi / slices) cos(pi / stacks) of the radius.
    const float pi = glm::pi<float>();
    m_sphereEnclosing = 1.0f / (std::cos(pi / kSphereSlices) * std::cos(pi / kSphereStacks));
}

DeferredRenderer::~DeferredRenderer() = default;

void DeferredRenderer::updateFrame(const Camera& camera, glm::ivec2 size, const SceneLighting& lighting) {
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    Scene scene;
    scene.ambient = lighting.ambient;
    scene.directionalLights = {lighting.moon};
    m_frame.update(camera, aspect, scene);
    m_frame.bind();
    m_view = camera.viewMatrix();
    m_projection = camera.projectionMatrix(aspect);
    m_near = camera.nearPlane();
}

void DeferredRenderer::prepareTargets(glm::ivec2 size) {
    if (m_gBuffer.resize(size) || m_size != size) {
        FramebufferOptions options;
        options.colorFormats = {GL_RGBA16F};
        m_lightBuffer = Framebuffer(size.x, size.y, options);
        m_size = size;
    }
}

void DeferredRenderer::renderGeometry(const DrawList& items, const Camera& camera, glm::ivec2 size) {
    prepareTargets(size);
    updateFrame(camera, size, SceneLighting{});
    PassDescription pass = passInto(m_gBuffer.target());
    pass.clear.color = pass.clear.depth = pass.clear.stencil = true;
    pass.clear.colorValue = glm::vec4(0.0f);
    pass.state.cull = CullMode::None;   // the Acropolis has open meshes (the floor seen from below, the wall's ends)
    beginPass(pass);
    m_programs.geometry->use();
    for (const DrawItem& item : items) {
        m_geometryUniforms->apply(item);
        item.mesh->draw();
    }
}

void DeferredRenderer::render(const DrawList& items, const std::vector<PointLight>& lights, const SceneLighting& lighting,
                              const Camera& camera, glm::ivec2 size, const DeferredSettings& settings) {
    const GLuint output = StateCache::current().drawFramebuffer();
    const bool needsGBuffer = settings.mode != LightingMode::Forward || settings.view != DeferredView::Final;
    if (needsGBuffer && !settings.reuseGBuffer) renderGeometry(items, camera, size);
    beginLighting(camera, size, lighting);
    if (settings.view == DeferredView::Final && settings.mode == LightingMode::Tiled) {
        // One pass, straight into the output: ambient light and every tile's lights.
        m_stats.lights = static_cast<int>(lights.size());
        StateCache::current().bindFramebuffer(output);
        drawTiled(lights, lighting, settings, false);
        return;
    }
    lightPointLights(items, lights, lighting, settings);
    present(output, settings);
}

void DeferredRenderer::beginLighting(const Camera& camera, glm::ivec2 size, const SceneLighting& lighting) {
    m_stats = DeferredStats{};
    prepareTargets(size);
    updateFrame(camera, size, lighting);
}

void DeferredRenderer::lightPointLights(const DrawList& items, const std::vector<PointLight>& lights,
                                        const SceneLighting& lighting, const DeferredSettings& settings) {
    m_stats.lights = static_cast<int>(lights.size());
    if (settings.view == DeferredView::Final && settings.mode == LightingMode::Forward) {
        drawForward(items, lights, lighting, settings);
    } else if (settings.view == DeferredView::Final) {
        // The light buffer gets the G-buffer's depth and stencil (a copy: a pass
        // may not sample a texture it also depth-tests against); the ambient
        // pass fills it and the volumes add to it, or the tiled pass does both.
        copyDepthToLightBuffer();
        if (settings.mode == LightingMode::Tiled) {
            StateCache::current().bindFramebuffer(m_lightBuffer.id());
            drawTiled(lights, lighting, settings, false);
        } else {
            drawAmbient(lighting, settings);
            drawVolumes(lights, settings, false);
        }
    } else if (settings.view == DeferredView::Overdraw) {
        // Counts, added up in the light buffer's red channel.
        copyDepthToLightBuffer();
        PassDescription pass = passInto(m_lightBuffer);
        pass.clear.color = true;
        pass.clear.colorValue = glm::vec4(0.0f);
        beginPass(pass);
        drawVolumes(lights, settings, true);
    } else if (settings.view == DeferredView::TileCounts) {
        StateCache::current().bindFramebuffer(m_lightBuffer.id());
        drawTiled(lights, lighting, settings, true);
    }
    StateCache::current().bindFramebuffer(m_lightBuffer.id());
}

void DeferredRenderer::copyDepthToLightBuffer() {
    STOA_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, m_gBuffer.target().id()));
    STOA_GL_CALL(glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_lightBuffer.id()));
    STOA_GL_CALL(glBlitFramebuffer(0, 0, m_size.x, m_size.y, 0, 0, m_size.x, m_size.y, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                      GL_NEAREST));
    StateCache::current().forget();
}

void DeferredRenderer::bindGBuffer(const Program& program) const {
    m_gBuffer.bindTextures(kGBufferUnit);
    program.set("uAlbedoSpecular", kGBufferUnit);
    program.set("uPackedNormal", kGBufferUnit + 1);
    program.set("uDepth", kGBufferUnit + 2);
    program.set("uInverseProjection", glm::inverse(m_projection));
    program.set("uViewport", glm::vec2(m_size));
}

void DeferredRenderer::setAmbientUniforms(const Program& program, const SceneLighting& lighting,
                                          const DeferredSettings& settings) const {
    program.set("uShininess", settings.shininess);
    program.set("uMoonDirectionView", glm::mat3(m_view) * lighting.moon.direction);
    program.set("uSky", lighting.sky);
    program.set("uAmbientOcclusion", kAmbientOcclusionUnit);
    program.set("uHasAmbientOcclusion", settings.ambientOcclusion != nullptr);
    if (settings.ambientOcclusion) settings.ambientOcclusion->bind(kAmbientOcclusionUnit);
}

void DeferredRenderer::drawAmbient(const SceneLighting& lighting, const DeferredSettings& settings) {
    beginPass(passInto(m_lightBuffer, RenderState::overlay()));
    const Program& program = *m_programs.ambient;
    program.use();
    bindGBuffer(program);
    setAmbientUniforms(program, lighting, settings);
    m_overlay.draw(program, {0, 0, m_size.x, m_size.y});
}

void DeferredRenderer::uploadLights(const std::vector<PointLight>& lights, const std::vector<float>& reaches) {
    std::vector<glm::vec4> texels;
    texels.reserve(3 * lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const glm::vec3 centre = glm::vec3(m_view * glm::vec4(lights[i].position, 1.0f));
        texels.emplace_back(centre, reaches.empty() ? 0.0f : reaches[i]);
        texels.emplace_back(lights[i].color, 0.0f);
        texels.emplace_back(lights[i].attenuation, 0.0f);
    }
    m_lightTexels.upload(texels);
}

void DeferredRenderer::drawVolumes(const std::vector<PointLight>& lights, const DeferredSettings& settings, bool countOnly) {
    if (lights.empty()) return;   // nothing to add
    const RenderState state = studentCode().deferred.lightVolumeState();   // the student's
    PassDescription pass = passInto(m_lightBuffer, state);
    beginPass(pass);
    const Program& program = *m_programs.lightVolume;
    program.use();
    bindGBuffer(program);
    program.set("uCutoff", settings.cutoff);
    program.set("uShininess", settings.shininess);
    program.set("uCountOnly", countOnly);
    const GLint center = program.uniformLocation("uCenterView");
    const GLint radius = program.uniformLocation("uRadius");
    const GLint position = program.uniformLocation("uLightPosition");
    const GLint color = program.uniformLocation("uLightColor");
    const GLint attenuation = program.uniformLocation("uLightAttenuation");
    const GLint reachLocation = program.uniformLocation("uLightReach");
    for (const PointLight& light : lights) {
        const float reach = studentCode().deferred.lightReach(light, settings.cutoff);   // the student's
        if (!(reach > 0.0f)) continue;
        const glm::vec3 centre = glm::vec3(m_view * glm::vec4(light.position, 1.0f));
        if (centre.z - reach * m_sphereEnclosing > -m_near) continue;   // wholly in front of the near plane: nothing to see
        program.setAt(center, centre);
        program.setAt(radius, reach * m_sphereEnclosing);
        program.setAt(position, centre);
        program.setAt(color, light.color);
        program.setAt(attenuation, light.attenuation);
        program.setAt(reachLocation, reach);
        m_sphere.draw();
        ++m_stats.lightsDrawn;
    }
}

const std::vector<DepthRange>& DeferredRenderer::tileDepthRanges(const TileGrid& grid) {
    // The G-buffer's depth, rows from the bottom as the tiles count them, into
    // a buffer kept between frames (a new one would be cleared first: 8 MB at 1080p).
    m_depthPixels.resize(static_cast<std::size_t>(m_size.x) * static_cast<std::size_t>(m_size.y));
    m_gBuffer.target().readPixels(-1, 0, 0, m_size.x, m_size.y, GL_DEPTH_COMPONENT, GL_FLOAT, m_depthPixels.data());
    return m_depthRanges->compute(m_depthPixels.data(), m_size, m_projection, grid);
}

void DeferredRenderer::assignWithFramework(const std::vector<LightSphere>& spheres, const TileGrid& grid,
                                           const std::vector<DepthRange>& depths) {
#if STOA_FRAMEWORK_TILE_LISTS
    m_binner->assign(spheres, m_projection, m_near, grid, depths, m_tiles);
#else
    (void)spheres, (void)grid, (void)depths;
#endif
}

void DeferredRenderer::drawTiled(const std::vector<PointLight>& lights, const SceneLighting& lighting,
                                 const DeferredSettings& settings, bool countOnly) {
    std::vector<float> reaches;
    std::vector<LightSphere> spheres;
    reaches.reserve(lights.size());
    spheres.reserve(lights.size());
    for (const PointLight& light : lights) {
        const float reach = studentCode().deferred.lightReach(light, settings.cutoff);   // the student's
        reaches.push_back(reach);
        spheres.push_back({glm::vec3(m_view * glm::vec4(light.position, 1.0f)), reach});
    }
    TileGrid grid;
    grid.viewport = m_size;
    grid.tileSize = settings.tileSize;
    const std::vector<DepthRange>& depths = tileDepthRanges(grid);
    // The framework's assignment is in the course's own tree, not in the student
    // release (it would be lab 08's answer): there the student's lists draw everywhere.
    if (settings.tileLists == TileListSource::Framework && m_binner)
        assignWithFramework(spheres, grid, depths);   // the same lists, faster
    else
        m_tiles = studentCode().deferred.buildTileLightLists(spheres, m_projection, m_near, grid, depths);   // the student's
    STOA_ASSERT(m_tiles.offsets.size() == static_cast<std::size_t>(grid.tileCount()) + 1,
                "buildTileLightLists() must return tileCount() + 1 offsets");
    STOA_ASSERT(static_cast<std::size_t>(m_tiles.offsets.back()) == m_tiles.lights.size(),
                "buildTileLightLists(): the last offset must equal the length of the lists");
    m_stats.tileListEntries = static_cast<long>(m_tiles.lights.size());
    uploadLights(lights, reaches);
    m_tileOffsets.upload(m_tiles.offsets);
    m_tileLights.upload(m_tiles.lights);

    // Into the framebuffer bound now, over all of it, replacing what is there.
    beginPass(passInto(m_size, RenderState::overlay()));
    const Program& program = *m_programs.tiled;
    program.use();
    bindGBuffer(program);
    setAmbientUniforms(program, lighting, settings);
    m_lightTexels.bind(kLightsUnit);
    m_tileOffsets.bind(kTileOffsetsUnit);
    m_tileLights.bind(kTileLightsUnit);
    program.set("uLights", kLightsUnit);
    program.set("uTileOffsets", kTileOffsetsUnit);
    program.set("uTileLights", kTileLightsUnit);
    program.set("uTileSize", settings.tileSize);
    program.set("uTileColumns", grid.tiles().x);
    program.set("uCutoff", settings.cutoff);
    program.set("uCountOnly", countOnly);
    m_overlay.draw(program, {0, 0, m_size.x, m_size.y});
}

void DeferredRenderer::drawForward(const DrawList& items, const std::vector<PointLight>& lights,
                                   const SceneLighting& lighting, const DeferredSettings& settings) {
    uploadLights(lights, {});
    PassDescription pass = passInto(m_lightBuffer);
    pass.clear.color = pass.clear.depth = true;
    pass.clear.colorValue = glm::vec4(lighting.sky, 1.0f);
    pass.state.cull = CullMode::None;
    beginPass(pass);
    const Program& program = *m_programs.forward;
    program.use();
    m_lightTexels.bind(kLightsUnit);
    program.set("uLights", kLightsUnit);
    program.set("uLightCount", static_cast<int>(lights.size()));
    program.set("uCutoff", settings.cutoff);
    program.set("uShininess", settings.shininess);
    program.set("uMoonDirectionView", glm::mat3(m_view) * lighting.moon.direction);
    for (const DrawItem& item : items) {
        m_forwardUniforms->apply(item);
        item.mesh->draw();
    }
}

void DeferredRenderer::present(GLuint target, const DeferredSettings& settings) {
    StateCache::current().bindFramebuffer(target);
    beginPass(passInto(m_size, RenderState::overlay()));
    const Program& program = *m_programs.views;
    program.use();
    bindGBuffer(program);
    int mode = kPresent;
    switch (settings.view) {
    case DeferredView::Final: mode = kPresent; break;
    case DeferredView::Albedo: mode = kAlbedo; break;
    case DeferredView::Normals: mode = kNormals; break;
    case DeferredView::Positions: mode = kPositions; break;
    case DeferredView::Specular: mode = kSpecular; break;
    case DeferredView::Overdraw:
    case DeferredView::TileCounts: mode = kHeat; break;
    }
    m_lightBuffer.bindColorTexture(kImageUnit);
    program.set("uImage", kImageUnit);
    program.set("uMode", mode);
    program.set("uHeatScale", settings.heatScale);
    program.set("uInverseView", glm::inverse(m_view));
    m_overlay.draw(program, {0, 0, m_size.x, m_size.y});
}

} // namespace stoa
