#include "CoursePasses.hpp"

#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/geometry/Material.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/CubeMap.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/glm.hpp>

#include <algorithm>

namespace stoa {

namespace {

constexpr int kNormalMapUnit = MeshObject::kFirstFreeTextureUnit;   // beside the diffuse and specular maps
constexpr int kSkyUnit = 3;
constexpr int kFirstCascadeUnit = 12;   // 12..15: clear of the G-buffer's, the tiles' and the occlusion's
constexpr float kCascadeLambda = 0.75f;
constexpr int kOcclusionKernelSize = 32;   // samples of the student's SSAO kernel

// Green, yellow, orange, red: level 0 (full detail) to 3, as lab 06's overview.
glm::vec3 levelTint(int level) {
    static const glm::vec3 tints[] = {{0.2f, 0.85f, 0.3f}, {0.95f, 0.9f, 0.2f}, {1.0f, 0.55f, 0.1f}, {0.95f, 0.2f, 0.15f}};
    return tints[std::min(std::max(level, 0), 3)];
}

float aspectOf(glm::ivec2 size) { return static_cast<float>(size.x) / static_cast<float>(size.y); }

// A pass that needs a student's function that is still a stub: it is left out
// of this frame, and the frame's stats say so.
void switchOff(CourseStats& stats, const char* pass, const NotImplemented& stub) {
    stats.switchedOff.push_back(std::string(pass) + ": " + stub.function() +
                                (stub.lab().empty() ? "" : " (lab " + stub.lab() + ")"));
}

// Lab 06: each item against the camera's frustum, then its level from its size
// on screen (the student's isVisible and levelOf, where handed over).
class CullingPass final : public CourseFramePass {
public:
    PassSignature signature() const override { return {"culling and LOD", {}, FrameTarget::Levels}; }
    CoursePass stage() const override { return CoursePass::Culling; }
    void run(CourseFrame& frame) override {
        const std::vector<CourseItem>& items = frame.items;
        std::vector<int>& levels = frame.targets.levels;
        CourseStats& stats = frame.stats;
        stats.objects = static_cast<int>(items.size());
        levels.assign(items.size(), 0);
        const glm::mat4 viewProjection = frame.camera.projectionMatrix(aspectOf(frame.size)) * frame.view;
        const CullingFunctions& culling = studentCode().culling;
        try {
            classify(frame, culling, viewProjection);
        } catch (const NotImplemented& stub) {   // lab 06 unfinished: every item drawn, at full detail
            switchOff(stats, "culling and LOD", stub);
            frame.cullingStubbed = true;
            stats.culled = stats.tooSmall = 0;
            stats.perLevel = {};
            stats.perLevel[0] = static_cast<int>(items.size());
            levels.assign(items.size(), 0);
        }
    }

private:
    void classify(CourseFrame& frame, const CullingFunctions& culling, const glm::mat4& viewProjection) {
        const std::vector<CourseItem>& items = frame.items;
        std::vector<int>& levels = frame.targets.levels;
        CourseStats& stats = frame.stats;
        for (std::size_t i = 0; i < items.size(); ++i) {
            const CourseItem& item = items[i];
            STOA_ASSERT(!item.levels.empty() && item.levels.front() != nullptr, "CourseItem: needs at least one level");
            const int levelCount = static_cast<int>(item.levels.size());
            int level = 0;
            if (frame.settings.culling && item.sphere.radius > 0.0f) {
                if (culling.isVisible && !culling.isVisible(item.sphere, viewProjection)) {   // the student's
                    levels[i] = -2;
                    ++stats.culled;
                    continue;
                }
                if (culling.levelOf) level = culling.levelOf(item.sphere, frame.camera, frame.size.y, levelCount);
                if (level < 0) {
                    levels[i] = -1;
                    ++stats.tooSmall;
                    continue;
                }
                level = std::min(level, levelCount - 1);
            }
            levels[i] = level;
            ++stats.perLevel[static_cast<std::size_t>(std::min(level, 3))];
        }
    }
};

// Lab 05: the sun's cascades (splits, slices and matrices from the student's
// code), each map drawn with the casters culled against it, the crowd's too.
class CascadePass final : public CourseFramePass {
public:
    explicit CascadePass(const CoursePrograms& programs) : m_depth(*programs.depth), m_agentsDepth(*programs.agentsDepth) {}
    PassSignature signature() const override { return {"cascaded shadows", FrameTarget::Levels, FrameTarget::CascadeMaps}; }
    CoursePass stage() const override { return CoursePass::Shadows; }
    void run(CourseFrame& frame) override {
        ShadowCascades& cascades = frame.targets.cascades;
        cascades.clear();   // none: the sun pass lights without shadows
        const ShadowFunctions& code = studentCode().shadows;
        if (!frame.settings.shadows || !code.cascadeSplits || !code.frustumSliceCorners || !code.cascadeLightMatrix) return;
        const CourseSettings& settings = frame.settings;
        const int count = std::min(std::max(settings.cascades, 1), ShadowCascades::kMaxCascades);
        const GLuint previous = StateCache::current().drawFramebuffer();
        try {
            cascades.split(frame.camera, std::min(settings.shadowFar, frame.camera.farPlane()), count, kCascadeLambda);
            for (int i = 0; i < count; ++i) {
                Framebuffer& map = cascades.fit(i, frame.camera, aspectOf(frame.size), frame.lighting.sunDirection,
                                                settings.shadowMapSize, frame.lighting.sceneMin, frame.lighting.sceneMax);
                drawCasters(frame, map, cascades.matrix(i));
            }
        } catch (const NotImplemented& stub) {   // lab 05 unfinished: the sun lights without shadows
            switchOff(frame.stats, "cascaded shadows", stub);
            cascades.clear();
        }
        StateCache::current().bindFramebuffer(previous);
    }

private:
    void drawCasters(const CourseFrame& frame, Framebuffer& map, const glm::mat4& matrix) {
        PassDescription pass = passInto(map);
        pass.clear.depth = true;
        pass.state.cull = CullMode::None;   // open meshes (the floor, the wall's ends) cast from both sides
        beginPass(pass);
        m_depth.use();
        m_depth.set("uLightSpaceMatrix", matrix);
        const CullingFunctions& culling = studentCode().culling;
        const std::vector<int>& levels = frame.targets.levels;
        for (std::size_t j = 0; j < frame.items.size(); ++j) {
            const CourseItem& item = frame.items[j];
            const bool cullable = frame.settings.culling && item.sphere.radius > 0.0f && !frame.cullingStubbed;
            if (cullable && culling.isVisible && !culling.isVisible(item.sphere, matrix)) continue;   // not in this cascade
            // Seen by the camera: its level there; unseen (a shadow from outside the view): the coarsest.
            const int level = levels[j] >= 0 ? levels[j] : static_cast<int>(item.levels.size()) - 1;
            m_depth.set("uModel", item.model);
            item.levels[static_cast<std::size_t>(level)]->draw();
        }
        if (frame.hasCrowd()) {
            FrameBlock block{};
            block.view = glm::mat4(1.0f);
            block.projection = matrix;
            m_lightFrame.update(block);
            m_lightFrame.bind();
            frame.crowd->renderer->drawAgentsWith(*frame.crowd->simulation, m_agentsDepth, frame.crowd->options);
        }
    }

    const Program& m_depth;
    const Program& m_agentsDepth;
    FrameUniforms m_lightFrame;   // a cascade's matrix as the projection, for the agents' depth pass
};

// Lab 08's G-buffer, filled with the items at their levels (lab 04's normal
// maps bend their surfaces) and the crowd's characters (lab 10).
class GeometryPass final : public CourseFramePass {
public:
    explicit GeometryPass(const CoursePrograms& programs) : m_geometry(*programs.geometry), m_agents(*programs.agents) {}
    PassSignature signature() const override { return {"G-buffer", FrameTarget::Levels, FrameTarget::GBuffer}; }
    CoursePass stage() const override { return CoursePass::Geometry; }
    void run(CourseFrame& frame) override {
        // The deferred renderer's own geometry pass with nothing to draw: its
        // targets at this size, its frame block for this camera, the G-buffer
        // cleared and bound for the draws below.
        frame.targets.deferred.renderGeometry({}, frame.camera, frame.size);
        static const Material grey;
        m_geometry.use();
        m_geometry.set("uNormalMap", kNormalMapUnit);
        m_geometry.set("uDiffuseMap", MeshObject::kDiffuseMapUnit);
        const bool tinted = frame.settings.view == CourseView::LevelsOfDetail;
        const std::vector<int>& levels = frame.targets.levels;
        for (std::size_t i = 0; i < frame.items.size(); ++i) {
            if (levels[i] < 0) continue;
            const CourseItem& item = frame.items[i];
            const Material& material = item.material ? *item.material : grey;
            m_geometry.set("uModel", item.model);
            m_geometry.set("uNormalMatrix", item.normalMatrix);
            m_geometry.set("uMaterial.diffuse", material.diffuse);
            m_geometry.set("uMaterial.specular", material.specular);
            m_geometry.set("uHasDiffuseMap", item.diffuseMap != nullptr);
            if (item.diffuseMap) item.diffuseMap->bind(MeshObject::kDiffuseMapUnit);
            const bool bumped = frame.settings.normalMaps && item.normalMap != nullptr;
            m_geometry.set("uHasNormalMap", bumped);
            if (bumped) item.normalMap->bind(kNormalMapUnit);
            const bool tintThis = tinted && item.sphere.radius > 0.0f;
            m_geometry.set("uTint", tintThis ? levelTint(levels[i]) : glm::vec3(1.0f));
            m_geometry.set("uTintAmount", tintThis ? 0.85f : 0.0f);
            item.levels[static_cast<std::size_t>(levels[i])]->draw();
        }
        if (frame.hasCrowd()) {
            const CrowdSimulation& simulation = *frame.crowd->simulation;
            frame.crowd->renderer->drawAgentsWith(simulation, m_agents, frame.crowd->options);
            frame.stats.agents = static_cast<int>(std::count_if(simulation.agents().begin(), simulation.agents().end(),
                                                                [](const CrowdAgent& agent) { return agent.alive; }));
        }
    }

private:
    const Program& m_geometry;
    const Program& m_agents;
};

// Lab 09: occlusion from the G-buffer with the student's kernel, blurred.
class OcclusionPass final : public CourseFramePass {
public:
    PassSignature signature() const override { return {"ambient occlusion", FrameTarget::GBuffer, FrameTarget::Occlusion}; }
    CoursePass stage() const override { return CoursePass::Occlusion; }
    bool enabled(const CourseFrame& frame) const override { return frame.settings.ambientOcclusion; }
    void run(CourseFrame& frame) override {
        CourseTargets& targets = frame.targets;
        if (!targets.occlusion.hasKernel()) {   // lab 09 not handed over, or still a stub
            if (!targets.occlusionStub.empty()) frame.stats.switchedOff.push_back("ambient occlusion: " + targets.occlusionStub);
            return;
        }
        targets.occlusion.render(targets.deferred, frame.size, OcclusionSettings{});
        frame.deferred.ambientOcclusion = &targets.occlusion.blurred();
    }
};

// Lab 08: the ambient light (times the occlusion) and the point lights in
// tiles, into the light buffer; or the tiles' counts for that view.
class PointLightPass final : public CourseFramePass {
public:
    PassSignature signature() const override {
        return {"ambient and point lights", FrameTarget::GBuffer | FrameTarget::Occlusion, FrameTarget::LightBuffer};
    }
    CoursePass stage() const override { return CoursePass::Lighting; }
    void run(CourseFrame& frame) override {
        DeferredRenderer& deferred = frame.targets.deferred;
        deferred.beginLighting(frame.camera, frame.size, frame.sceneLighting);
        deferred.lightPointLights({}, frame.lighting.pointLights, frame.sceneLighting, frame.deferred);
        frame.stats.tileListEntries = deferred.stats().tileListEntries;
    }
};

// Lab 05: the sun on the G-buffer, tested against the cascades
// (shadows.glsl), added to the light buffer; or each cascade tinted.
class SunPass final : public CourseFramePass {
public:
    explicit SunPass(const CoursePrograms& programs) : m_sun(*programs.sun) {}
    PassSignature signature() const override {
        return {"sun", FrameTarget::GBuffer | FrameTarget::CascadeMaps, FrameTarget::LightBuffer};
    }
    CoursePass stage() const override { return CoursePass::Lighting; }
    bool enabled(const CourseFrame& frame) const override { return frame.lit(); }
    void run(CourseFrame& frame) override {
        const CourseSettings& settings = frame.settings;
        const CourseLighting& lighting = frame.lighting;
        const ShadowCascades& cascades = frame.targets.cascades;
        const bool cascadeView = settings.view == CourseView::Cascades;
        RenderState state = RenderState::overlay();
        state.blend = cascadeView ? BlendMode::Opaque : BlendMode::Additive;
        const glm::ivec2 size = frame.targets.deferred.gBuffer().size();
        m_sun.use();
        frame.targets.deferred.bindGBuffer(m_sun);
        m_sun.set("uInverseView", glm::inverse(frame.view));
        m_sun.set("uSunDirectionView", glm::normalize(glm::mat3(frame.view) * lighting.sunDirection));
        m_sun.set("uSunDirectionWorld", glm::normalize(lighting.sunDirection));
        m_sun.set("uSunColor", lighting.sunColor);
        m_sun.set("uShininess", frame.deferred.shininess);
        cascades.setUniforms(m_sun, kFirstCascadeUnit, settings.shadowMapSize, frame.camera.farPlane(), true);
        m_sun.set("uCascadeCount", std::max(cascades.count(), 1));
        m_sun.set("uShadowsEnabled", cascades.count() > 0);
        m_sun.set("uPcfMode", static_cast<int>(settings.pcf));
        m_sun.set("uCascadeColors", cascadeView);
        frame.targets.overlay.draw(m_sun, {0, 0, size.x, size.y}, state);   // into the light buffer, still bound
    }

private:
    const Program& m_sun;
};

// Lab 06's skybox where the G-buffer's depth is still the far plane.
class SkyPass final : public CourseFramePass {
public:
    explicit SkyPass(const CoursePrograms& programs)
        : m_sky(*programs.sky), m_cubeMap(CubeMap::fromFolder(paths::assetsDir() / "sky")), m_cube(shapes::cube(2.0f)) {}
    PassSignature signature() const override { return {"sky", FrameTarget::LightBuffer, FrameTarget::LightBuffer}; }
    CoursePass stage() const override { return CoursePass::Sky; }
    bool enabled(const CourseFrame& frame) const override { return frame.lit() && frame.settings.sky; }
    void run(CourseFrame& frame) override {
        RenderState state;
        state.depth.func = GL_LEQUAL;   // at the far plane: only where the G-buffer's depth is still 1
        state.depth.write = false;
        state.cull = CullMode::None;
        beginPass(passInto(frame.targets.deferred.lightBuffer(), state));
        m_sky.use();
        m_cubeMap.bind(kSkyUnit);
        m_sky.set("uSky", kSkyUnit);
        m_cube.draw();
    }

private:
    const Program& m_sky;
    CubeMap m_cubeMap;
    GpuMesh m_cube;
};

// Lab 10: the crowd's world markers (samples, crumbs, bases, trails), lit by
// the sun and the ambient light, depth-tested against the G-buffer's copy.
class MarkerPass final : public CourseFramePass {
public:
    PassSignature signature() const override { return {"crowd markers", FrameTarget::LightBuffer, FrameTarget::LightBuffer}; }
    CoursePass stage() const override { return CoursePass::Sky; }
    bool enabled(const CourseFrame& frame) const override {
        return frame.lit() && frame.hasCrowd() && frame.crowd->options.markers;
    }
    void run(CourseFrame& frame) override {
        const float aspect = aspectOf(frame.targets.deferred.gBuffer().size());
        Scene lights;
        lights.ambient = frame.lighting.ambient;
        lights.directionalLights = {DirectionalLight{frame.lighting.sunDirection, frame.lighting.sunColor}};
        m_markerFrame.update(frame.camera, aspect, lights);
        m_markerFrame.bind();
        RenderState state;
        state.cull = CullMode::None;
        beginPass(passInto(frame.targets.deferred.lightBuffer(), state));
        CrowdView view;
        view.view = frame.view;
        view.projection = frame.camera.projectionMatrix(aspect);
        view.eye = frame.camera.eyePosition();
        CrowdDrawOptions options = frame.crowd->options;
        options.trails = options.trails || frame.settings.view == CourseView::Trails;
        frame.crowd->renderer->drawMarkersWith(*frame.crowd->simulation, view, options);
    }

private:
    FrameUniforms m_markerFrame;   // the camera, the ambient light and the sun
};

// What glows by itself, given by the caller (lab 07's sparks).
class GlowPass final : public CourseFramePass {
public:
    PassSignature signature() const override { return {"glow", FrameTarget::LightBuffer, FrameTarget::LightBuffer}; }
    CoursePass stage() const override { return CoursePass::Sky; }
    bool enabled(const CourseFrame& frame) const override { return frame.lit() && static_cast<bool>(frame.glow); }
    void run(CourseFrame& frame) override { frame.glow(frame.targets.deferred.lightBuffer()); }
};

// The light buffer, clamped (or a G-buffer view), into the output.
class PresentPass final : public CourseFramePass {
public:
    PassSignature signature() const override {
        return {"present", FrameTarget::LightBuffer | FrameTarget::GBuffer, FrameTarget::Output};
    }
    CoursePass stage() const override { return CoursePass::Present; }
    void run(CourseFrame& frame) override { frame.targets.deferred.present(frame.output, frame.deferred); }
};

// The "occlusion" view: lab 09's blurred occlusion in grey (white without it).
class OcclusionViewPass final : public CourseFramePass {
public:
    explicit OcclusionViewPass(const CoursePrograms& programs) : m_grey(*programs.grey) {}
    PassSignature signature() const override { return {"occlusion view", FrameTarget::Occlusion, FrameTarget::Output}; }
    CoursePass stage() const override { return CoursePass::Present; }
    bool enabled(const CourseFrame& frame) const override { return frame.settings.view == CourseView::AmbientOcclusion; }
    void run(CourseFrame& frame) override {
        StateCache::current().bindFramebuffer(frame.output);
        beginPass(passInto(frame.size, RenderState::overlay()));
        if (frame.deferred.ambientOcclusion) {
            m_grey.use();
            frame.targets.occlusion.blurred().bind(kSkyUnit);
            m_grey.set("uImage", kSkyUnit);
            frame.targets.overlay.draw(m_grey, {0, 0, frame.size.x, frame.size.y});
        } else {
            STOA_GL_CALL(glClearColor(1.0f, 1.0f, 1.0f, 1.0f));   // no occlusion: everything fully open
            STOA_GL_CALL(glClear(GL_COLOR_BUFFER_BIT));
        }
    }

private:
    const Program& m_grey;
};

// The "ids" view: lab 07's ID pass over the drawn items (each its
// CourseItem::id, packed by the student's packObjectId() into a GL_RGBA8UI
// target), shown in false colour.
class IdPass final : public CourseFramePass {
public:
    explicit IdPass(const CoursePrograms& programs) : m_ids(*programs.ids), m_idView(*programs.idView) {}
    PassSignature signature() const override {
        return {"ids view", FrameTarget::Levels, FrameTarget::IdBuffer | FrameTarget::Output};
    }
    CoursePass stage() const override { return CoursePass::Present; }
    bool enabled(const CourseFrame& frame) const override { return frame.settings.view == CourseView::Ids; }
    void run(CourseFrame& frame) override {
        const glm::ivec2 size = frame.size;
        if (!m_target || m_target->width() != size.x || m_target->height() != size.y) {
            FramebufferOptions options;
            options.colorFormats = {GL_RGBA8UI};
            m_target = std::make_unique<Framebuffer>(size.x, size.y, options);
        }
        PassDescription pass = passInto(*m_target);
        pass.clear.depth = true;
        pass.state.cull = CullMode::None;
        beginPass(pass);
        const GLuint background[4] = {0, 0, 0, 0};
        STOA_GL_CALL(glClearBufferuiv(GL_COLOR, 0, background));   // an integer target clears with its own call
        m_ids.use();
        const std::vector<int>& levels = frame.targets.levels;
        for (std::size_t i = 0; i < frame.items.size(); ++i) {
            if (levels[i] < 0) continue;
            m_ids.set("uModel", frame.items[i].model);
            m_ids.set("uObjectId", frame.items[i].id);
            frame.items[i].levels[static_cast<std::size_t>(levels[i])]->draw();
        }
        StateCache::current().bindFramebuffer(frame.output);
        m_idView.use();
        m_target->bindColorTexture(kSkyUnit);
        m_idView.set("uIds", kSkyUnit);
        frame.targets.overlay.draw(m_idView, {0, 0, size.x, size.y});
    }

private:
    const Program& m_ids;
    const Program& m_idView;
    std::unique_ptr<Framebuffer> m_target;   // GL_RGBA8UI
};

} // namespace

CourseTargets::CourseTargets(const CoursePrograms& programs)
    : deferred(programs.deferred), occlusion(*programs.occlusion, *programs.blur) {
    const OcclusionFunctions& code = studentCode().occlusion;   // the student's samples, where handed over
    try {
        if (code.ssaoKernel && code.ssaoNoise) occlusion.setKernel(code.ssaoKernel(kOcclusionKernelSize, 1), code.ssaoNoise(2));
    } catch (const NotImplemented& stub) {   // lab 09 unfinished: no ambient occlusion
        occlusionStub = stub.function() + (stub.lab().empty() ? "" : " (lab " + stub.lab() + ")");
    }
}

std::vector<std::unique_ptr<CourseFramePass>> makeCoursePasses(const CoursePrograms& programs) {
    std::vector<std::unique_ptr<CourseFramePass>> passes;
    passes.push_back(std::make_unique<CullingPass>());
    passes.push_back(std::make_unique<CascadePass>(programs));
    passes.push_back(std::make_unique<GeometryPass>(programs));
    passes.push_back(std::make_unique<OcclusionPass>());
    passes.push_back(std::make_unique<PointLightPass>());
    passes.push_back(std::make_unique<SunPass>(programs));
    passes.push_back(std::make_unique<SkyPass>(programs));
    passes.push_back(std::make_unique<MarkerPass>());
    passes.push_back(std::make_unique<GlowPass>());
    passes.push_back(std::make_unique<PresentPass>());
    passes.push_back(std::make_unique<OcclusionViewPass>(programs));
    passes.push_back(std::make_unique<IdPass>(programs));
    return passes;
}

} // namespace stoa
