#include <stoa/render/CourseRenderer.hpp>

#include "CoursePasses.hpp"

#include <stoa/camera/Camera.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/StateCache.hpp>

#include <algorithm>
#include <chrono>
#include <memory>

namespace stoa {

namespace {

constexpr float kShininess = 24.0f;     // DeferredSettings' default, for the sun as for the point lights

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
    : m_targets(std::make_unique<CourseTargets>(programs)), m_passes(makeCoursePasses(programs)) {
    checkPassOrder(passes());
}

CourseRenderer::~CourseRenderer() = default;

std::vector<PassSignature> CourseRenderer::passes() const {
    std::vector<PassSignature> signatures;
    for (const auto& pass : m_passes) signatures.push_back(pass->signature());
    return signatures;
}

const std::vector<int>& CourseRenderer::levels() const { return m_targets->levels; }

void CourseRenderer::endPass(CoursePass pass, bool timed) {
    if (timed) STOA_GL_CALL(glFinish());
    const double end = now();
    m_stats.seconds[static_cast<std::size_t>(pass)] += end - m_passStart;
    m_passStart = end;
}

namespace {

// What the deferred passes draw with: the tiles and the view (the occlusion
// pass adds its picture, where it draws one).
DeferredSettings deferredSettingsFor(const CourseSettings& settings) {
    DeferredSettings deferred;
    deferred.mode = LightingMode::Tiled;
    deferred.tileLists = TileListSource::Framework;   // the same lists as the student's function, without the wait
    deferred.shininess = kShininess;
    deferred.reuseGBuffer = true;
    switch (settings.view) {
    case CourseView::Albedo: deferred.view = DeferredView::Albedo; break;
    case CourseView::Normals: deferred.view = DeferredView::Normals; break;
    case CourseView::Positions: deferred.view = DeferredView::Positions; break;
    case CourseView::Specular: deferred.view = DeferredView::Specular; break;
    case CourseView::LightTiles: deferred.view = DeferredView::TileCounts; break;
    default: deferred.view = DeferredView::Final; break;
    }
    return deferred;
}

} // namespace

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

    CourseFrame frame{items,      lighting, camera, size,   settings, crowd, glow, output, camera.viewMatrix(),
                      *m_targets, m_stats,  deferredSettingsFor(settings), SceneLighting{}};
    frame.sceneLighting.ambient = lighting.ambient;
    frame.sceneLighting.moon = DirectionalLight{lighting.sunDirection, glm::vec3(0.0f)};   // the sun is the sun pass's
    frame.sceneLighting.sky = settings.sky ? glm::vec3(0.0f) : lighting.skyColor;

    for (const auto& pass : m_passes) {
        if (!pass->enabled(frame)) continue;
        pass->run(frame);
        endPass(pass->stage(), timed);
    }
    StateCache::current().bindFramebuffer(output);
    m_stats.totalSeconds = now() - start;
}

} // namespace stoa
