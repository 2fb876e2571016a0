#pragma once
// Every pass of the course in one frame: stoa-editor's deferred pipeline and
// its showcase (docs/showcase.md). A list of pass objects, each of which says
// what it reads and writes of the frame's targets (passes(),
// stoa/render/FramePass.hpp); the constructor checks their order. In order:
//
//   culling    each object's bounding sphere against the camera's frustum and
//              its level of detail from its size on screen (lab 06)
//   shadows    the sun's cascaded shadow maps: splits, slices and light
//              matrices from lab 05's code; the casters culled per cascade
//   geometry   the G-buffer (lab 08's packing), surfaces bent by their normal
//              maps (lab 04's tangent frame), a crowd's characters (lab 10)
//   occlusion  screen-space ambient occlusion from the G-buffer (lab 09)
//   lighting   ambient light and the point lights in tiles (lab 08), then the
//              sun, tested against the cascades (lab 05's shadows.glsl)
//   sky        the skybox where nothing was drawn (lab 06's skybox.glsl), then
//              what glows by itself, given by the caller (lab 07's sparks)
//   present    the lit picture (or a debug view) into the bound framebuffer
//
// The students' functions come in through the framework's student-code table
// (StudentCode: culling, shadows, deferred, occlusion), so the framework links
// without them. A culling, cascade or occlusion function that is unset, or
// still a stub (it throws NotImplemented), switches its own pass off
// (stats().switchedOff says which), so a program with those labs unfinished
// still draws the rest; the point lights' tiles (lab 08) are not optional.
// Their GLSL comes in through the programs' includes.
//
//   CourseRenderer renderer(CoursePrograms::load(loader));
//   renderer.render(items, lighting, camera, size, settings, nullptr);
//   std::printf("%.1f ms shadows\n", 1e3 * renderer.stats().seconds[int(CoursePass::Shadows)]);
#include <stoa/geometry/Bounds.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/render/CrowdRenderer.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/render/FramePass.hpp>
#include <stoa/render/ShadowRenderer.hpp>
#include <stoa/scene/Light.hpp>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace stoa {

class Camera;
class CourseFramePass;
class CrowdSimulation;
class Program;
class Texture2D;
struct CourseTargets;
struct Material;

/// One object to draw: its levels of detail, placement, material and maps.
struct CourseItem {
    std::vector<const GpuMesh*> levels;        // [0] the full mesh, then coarser ones; at least one
    glm::mat4 model{1.0f};                     // object -> world
    glm::mat3 normalMatrix{1.0f};              // the inverse transpose of model's 3x3
    const Material* material = nullptr;        // nullptr: a grey default
    const Texture2D* diffuseMap = nullptr;
    const Texture2D* normalMap = nullptr;      // tangent-space; nullptr: the mesh's own normals
    BoundingSphere sphere;                     // world space; radius 0: never culled, always full detail
    std::uint32_t id = 0;                      // lab 07's ID buffer (the "ids" view); 0: the background's
};

enum class CoursePass { Culling = 0, Shadows, Geometry, Occlusion, Lighting, Sky, Present, Count };
const char* toString(CoursePass pass);

/// What render() puts on the screen: the picture or one pass's debug view.
enum class CourseView {
    Final,
    Albedo, Normals, Positions, Specular, LightTiles,   // lab 08's G-buffer and tiles
    AmbientOcclusion,                                   // lab 09's blurred occlusion
    Cascades,                                           // lab 05: each cascade tinted
    LevelsOfDetail,                                     // lab 06: each object tinted by its level
    Trails,                                             // lab 10: the final picture with each agent's trail
    Ids                                                 // lab 07: each object's 32-bit id in false colour
};
/// The names the scene file and the renderer panel use: "final", "albedo",
/// "normals", "positions", "specular", "tiles", "occlusion", "cascades", "lod", "trails", "ids".
const char* toString(CourseView view);
/// The view called `name`; false when there is none.
bool courseViewFromName(const std::string& name, CourseView& view);
/// Every view's name, in the enum's order.
const std::vector<std::string>& courseViewNames();

struct CourseSettings {
    bool culling = true;             // false: every object drawn, at full detail
    bool shadows = true;
    PcfMode pcf = PcfMode::ThreeByThree;
    int cascades = 3;                // 1..ShadowCascades::kMaxCascades
    float shadowFar = 90.0f;         // view depth where the last cascade ends, metres
    int shadowMapSize = 1024;        // each cascade's, texels per side
    bool normalMaps = true;
    bool ambientOcclusion = true;
    bool sky = true;                 // the skybox; false: a plain sky colour
    CourseView view = CourseView::Final;
    /// Wait for the GPU after each pass (glFinish) so that stats().seconds are
    /// each pass's own time; slows the frame a little. For the benchmark.
    bool timePasses = false;
};

struct CourseLighting {
    glm::vec3 ambient{0.1f};
    glm::vec3 sunDirection{-0.4f, -1.0f, -0.3f};   // the way the light travels
    glm::vec3 sunColor{1.0f};
    glm::vec3 skyColor{0.55f, 0.68f, 0.82f};       // where nothing was drawn, without the skybox
    std::vector<PointLight> pointLights;
    glm::vec3 sceneMin{-100.0f, 0.0f, -100.0f};    // the casters' world bounds: the cascades' depth range
    glm::vec3 sceneMax{100.0f, 10.0f, 100.0f};
};

/// A crowd: its agents drawn into the G-buffer and the shadow maps, its world's
/// markers (samples, crumbs, bases) lit by the sun and the ambient light after
/// the sky, when options.markers (the ground it walks is the caller's items).
struct CourseCrowd {
    const CrowdSimulation* simulation = nullptr;
    CrowdRenderer* renderer = nullptr;
    CrowdDrawOptions options;
};

struct CourseStats {
    int objects = 0;                 // items given
    int culled = 0;                  // outside the frustum
    int tooSmall = 0;                // inside, but below the smallest size drawn
    std::array<int, 4> perLevel{};   // drawn at level 0, 1, 2, 3 (and coarser)
    int agents = 0;
    int pointLights = 0;
    long tileListEntries = 0;
    std::array<double, static_cast<int>(CoursePass::Count)> seconds{};   // CPU time, each pass's own with timePasses
    double totalSeconds = 0.0;
    /// The passes that switched themselves off this frame because a student's
    /// function they call is still a stub, each as "culling and LOD:
    /// isVisible() (lab 06_culling)": the rest of the frame is drawn without them.
    std::vector<std::string> switchedOff;
};

struct CoursePrograms {
    using Loader = std::function<const Program&(const std::string& vertex, const std::string& fragment)>;
    /// Loads every program the passes use (through `load`, which keeps them).
    static CoursePrograms load(const Loader& load);
    DeferredPrograms deferred;
    const Program* geometry = nullptr;       // course/geometry.vert + course/geometry.frag
    const Program* agents = nullptr;         // crowd/md2.vert + course/agents.frag
    const Program* depth = nullptr;          // shadows/depth.vert + shadows/depth.frag
    const Program* agentsDepth = nullptr;    // crowd/md2.vert + crowd/depth.frag
    const Program* sun = nullptr;            // basic/image.vert + course/sun.frag
    const Program* sky = nullptr;            // culling/skybox.vert + culling/skybox.frag
    const Program* occlusion = nullptr;      // basic/image.vert + ssao/ssao.frag
    const Program* blur = nullptr;           // basic/image.vert + ssao/blur.frag
    const Program* grey = nullptr;           // basic/image.vert + ssao/ao_view.frag
    const Program* ids = nullptr;            // picking/ids.vert + picking/ids.frag
    const Program* idView = nullptr;         // basic/image.vert + picking/id_view.frag
};

class CourseRenderer {
public:
    /// Needs a current context; loads the sky's cube map from assets/sky.
    explicit CourseRenderer(const CoursePrograms& programs);
    ~CourseRenderer();

    /// What glows by itself (lab 07's sparks): drawn after the sky into the
    /// light buffer, which is bound with a copy of the G-buffer's depth, under
    /// the camera's frame block; the function sets its own state.
    using GlowPass = std::function<void(const Framebuffer& lightBuffer)>;

    /// The whole frame at `size` pixels into the framebuffer bound when called.
    /// `crowd` may be nullptr; `glow` may be empty.
    void render(const std::vector<CourseItem>& items, const CourseLighting& lighting, const Camera& camera,
                glm::ivec2 size, const CourseSettings& settings, const CourseCrowd* crowd, const GlowPass& glow = {});

    const CourseStats& stats() const { return m_stats; }
    /// Each item's level in the last frame: -2 culled, -1 too small, else its level.
    const std::vector<int>& levels() const;
    /// The passes in the order render() runs them, with what each reads and
    /// writes; a pass that is off for a frame (a view, a setting, a lab not
    /// handed over) is skipped in it.
    std::vector<PassSignature> passes() const;

private:
    void endPass(CoursePass pass, bool timed);

    std::unique_ptr<CourseTargets> m_targets;
    std::vector<std::unique_ptr<CourseFramePass>> m_passes;
    CourseStats m_stats;
    double m_passStart = 0.0;
};

} // namespace stoa
