#pragma once
// Deferred shading's passes put together (labs 08-09), and the naive forward
// renderer it is measured against:
//
//   forward   every fragment of every triangle loops over all the lights
//   volumes   geometry pass into the G-buffer; ambient pass; one sphere per
//             light, each fragment of which lights the pixel under it
//   tiled     geometry pass; ambient pass; the lights sorted into screen tiles
//             on the CPU, each tile bounded by the depths its pixels see (read
//             back from the G-buffer), by the student's buildTileLightLists()
//             or the framework's own (DeferredSettings::tileLists); one
//             full-screen pass, each pixel looping over its tile's lights
//
// All three light with shaders/deferred/lighting.glsl: forward and the volumes
// into a 16-bit float light buffer, then copied, clamped, into the framebuffer
// bound when render() is called; the tiled pass straight into that framebuffer.
// Lab 08's app and benchmark and lab 09's app draw through render(); the
// course's renderer calls its passes one by one (beginLighting() and after).
//
// The student's functions reach it through the framework's student-code table
// (StudentCode::deferred), which the program fills at start-up; the student's
// GLSL (08_deferred/student/g_buffer.glsl) is in the programs the lab loads.
//
//   DeferredRenderer renderer(programs);
//   renderer.render(drawList, lights, lighting, camera, size, settings);

#include <stoa/gl/BufferTexture.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/RenderState.hpp>
#include <stoa/render/DeferredShading.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/render/GBuffer.hpp>
#include <stoa/render/TextureOverlay.hpp>
#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/Light.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace stoa {

class Camera;
class ObjectUniforms;
class Program;
class Texture2D;
class TileDepthRanges;   // private to libstoa (framework/src/render)
class TileLightBinner;   // private to libstoa, and only in the course's own tree

enum class LightingMode { Forward, Volumes, Tiled };

/// Who sorts the lights into tiles in the tiled mode. Student: the student's
/// buildTileLightLists() through the student-code table (what a lab's program
/// draws, and so what it grades). Framework: the framework's own assignment,
/// which gives the same lists, in the same order, much faster (the editor and
/// the showcase, whose frames must not wait for it; docs/framework.md).
enum class TileListSource { Student, Framework };

/// What render() shows: the lit picture, a channel of the G-buffer, or a heat map.
enum class DeferredView {
    Final,       // the lit picture
    Albedo,      // G-buffer albedo
    Normals,     // the unpacked view-space normals, n * 0.5 + 0.5
    Positions,   // the world position rebuilt from depth: fract() of each coordinate, a 1 m grid
    Specular,    // G-buffer specular strength
    Overdraw,    // how many light volumes cover each pixel (volumes' state, heat map)
    TileCounts   // how many lights each tile's list holds (heat map)
};

/// "forward", "volumes", "tiled"; "final", "albedo", ...
const char* toString(LightingMode mode);
const char* toString(DeferredView view);

/// The programs, loaded by the lab (their search path holds the student's
/// GLSL). They must outlive the renderer.
struct DeferredPrograms {
    /// The six through `load` (LabResources::loadProgram, for instance):
    ///   DeferredPrograms::load([&](const std::string& v, const std::string& f) -> const Program& {
    ///       return resources.loadProgram(v, f); });
    static DeferredPrograms load(const std::function<const Program&(const std::string&, const std::string&)>& load);

    const Program* geometry = nullptr;      // deferred/geometry.vert + deferred/geometry.frag
    const Program* forward = nullptr;       // deferred/forward.vert + deferred/forward.frag
    const Program* ambient = nullptr;       // basic/image.vert + deferred/ambient.frag
    const Program* lightVolume = nullptr;   // deferred/light_volume.vert + deferred/light_volume.frag
    const Program* tiled = nullptr;         // basic/image.vert + deferred/tiled.frag
    const Program* views = nullptr;         // basic/image.vert + deferred/views.frag
};

/// The light besides the point lights: ambient and one directional light.
struct SceneLighting {
    glm::vec3 ambient{0.06f, 0.07f, 0.1f};
    DirectionalLight moon{{0.4f, -1.0f, -0.6f}, {0.1f, 0.11f, 0.16f}};
    glm::vec3 sky{0.015f, 0.02f, 0.045f};
};

struct DeferredSettings {
    LightingMode mode = LightingMode::Volumes;
    DeferredView view = DeferredView::Final;
    float cutoff = 1.0f / 64.0f;   // where a light's brightest channel counts as gone (lighting.glsl)
    int tileSize = 16;             // pixels
    TileListSource tileLists = TileListSource::Student;
    float shininess = 24.0f;       // the Blinn-Phong exponent of every surface
    float heatScale = 64.0f;       // the light count the heat maps show as white
    /// Lab 09: the ambient occlusion, one value per pixel in .r, multiplying
    /// the ambient light. nullptr: none (1 everywhere).
    const Texture2D* ambientOcclusion = nullptr;
    /// Skip the geometry pass: renderGeometry() has just filled the G-buffer
    /// for the same items, camera and size (lab 09 reads it before lighting).
    bool reuseGBuffer = false;
};

/// What the last render() did, for the window's title line and the benchmark.
struct DeferredStats {
    int lights = 0;              // point lights given
    int lightsDrawn = 0;         // volumes: spheres drawn (reach > 0 and in front of the camera)
    long tileListEntries = 0;    // tiled: the lists' total length
};

class DeferredRenderer {
public:
    /// Needs a current context.
    explicit DeferredRenderer(const DeferredPrograms& programs);
    ~DeferredRenderer();

    /// The whole frame at `size` pixels into the framebuffer bound when called.
    void render(const DrawList& items, const std::vector<PointLight>& lights, const SceneLighting& lighting,
                const Camera& camera, glm::ivec2 size, const DeferredSettings& settings);

    /// The geometry pass alone into the G-buffer (binds it; the caller binds
    /// its own target again). For lab 09, which reads the G-buffer next, and the benchmark.
    void renderGeometry(const DrawList& items, const Camera& camera, glm::ivec2 size);

    /// Binds the G-buffer's textures and sets the uniforms of
    /// shaders/deferred/gbuffer_read.glsl on `program`, which must be in use:
    /// for a pass of the lab's own that reads the G-buffer (lab 09's occlusion).
    void bindGBuffer(const Program& program) const;

    /// The passes of render() one by one, for a renderer that adds its own
    /// between them (CourseRenderer: the shadowed sun, the sky):
    ///   renderGeometry(items, camera, size);            // or the caller's own draws into gBuffer()
    ///   beginLighting(camera, size, lighting);          // targets and frame block
    ///   lightPointLights(lights, lighting, settings);   // into lightBuffer(), left bound
    ///   ...the caller's passes into lightBuffer()...
    ///   present(output, settings);
    /// A final picture goes through the light buffer in every mode this way
    /// (render() lights the tiled one straight into its output).
    void beginLighting(const Camera& camera, glm::ivec2 size, const SceneLighting& lighting);
    /// The ambient light and the point lights (or, for the Overdraw and
    /// TileCounts views, their counts) into the light buffer, which is bound
    /// after; nothing for the G-buffer's own views.
    void lightPointLights(const DrawList& items, const std::vector<PointLight>& lights, const SceneLighting& lighting,
                          const DeferredSettings& settings);
    /// The light buffer (or settings.view of the G-buffer) into `target`.
    void present(GLuint target, const DeferredSettings& settings);

    const GBuffer& gBuffer() const { return m_gBuffer; }
    const Framebuffer& lightBuffer() const { return m_lightBuffer; }
    const DeferredStats& stats() const { return m_stats; }
    /// The lists of the last tiled frame.
    const TileLightLists& tileLists() const { return m_tiles; }

private:
    void updateFrame(const Camera& camera, glm::ivec2 size, const SceneLighting& lighting);
    void prepareTargets(glm::ivec2 size);
    void copyDepthToLightBuffer();
    void setAmbientUniforms(const Program& program, const SceneLighting& lighting, const DeferredSettings& settings) const;
    void drawForward(const DrawList& items, const std::vector<PointLight>& lights, const SceneLighting& lighting,
                     const DeferredSettings& settings);
    void drawAmbient(const SceneLighting& lighting, const DeferredSettings& settings);
    void drawVolumes(const std::vector<PointLight>& lights, const DeferredSettings& settings, bool countOnly);
    void drawTiled(const std::vector<PointLight>& lights, const SceneLighting& lighting, const DeferredSettings& settings,
                   bool countOnly);
    const std::vector<DepthRange>& tileDepthRanges(const TileGrid& grid);
    void assignWithFramework(const std::vector<LightSphere>& spheres, const TileGrid& grid,
                             const std::vector<DepthRange>& depths);
    void uploadLights(const std::vector<PointLight>& lights, const std::vector<float>& reaches);

    DeferredPrograms m_programs;
    GBuffer m_gBuffer;
    Framebuffer m_lightBuffer;       // RGBA16F and its own depth-stencil, a copy of the G-buffer's
    FrameUniforms m_frame;
    std::unique_ptr<ObjectUniforms> m_geometryUniforms;
    std::unique_ptr<ObjectUniforms> m_forwardUniforms;
    GpuMesh m_sphere;                // radius 1
    float m_sphereEnclosing = 1.0f;  // scale that makes the flat-faced mesh enclose the unit sphere
    BufferTexture m_lightTexels;
    BufferTexture m_tileOffsets;
    BufferTexture m_tileLights;
    TextureOverlay m_overlay;
    TileLightLists m_tiles;
    std::unique_ptr<TileDepthRanges> m_depthRanges;
    std::unique_ptr<TileLightBinner> m_binner;   // the framework's lists; null in a student release (no TileLightBinner.cpp)
    std::vector<float> m_depthPixels;            // the G-buffer's depth read back, kept between frames
    DeferredStats m_stats;
    glm::mat4 m_view{1.0f}, m_projection{1.0f};
    float m_near = 0.1f;
    glm::ivec2 m_size{0};
};

} // namespace stoa
