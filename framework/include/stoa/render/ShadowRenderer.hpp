#pragma once
// Shadow mapping's passes put together (lab 05): the lab's depth pass into the
// shadow map, then the scene lit by the one shadow-casting light through
// shaders/shadows/shadowed.frag, and optionally the map in a corner. With
// cascades, one map per slice of the camera's frustum and
// shaders/shadows/cascaded.frag. Lab 05's app and
// tests/benchmarks/shadow_benchmark.cpp both draw through it.
//
// The functions it calls that are the student's reach it through the
// framework's student-code table (StudentCode::shadows), which the program
// fills at start-up:
//
//   ShadowRenderer renderer(depth, shadowed, mapView);

#include <stoa/gl/Framebuffer.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/render/ShadowCascades.hpp>
#include <stoa/render/TextureOverlay.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <string>
#include <vector>

namespace stoa {

class Camera;
class Program;
class Scene;

/// How many shadow-map texels shadowFactor() averages (shadows.glsl's pcfMode).
enum class PcfMode { Single = 0, TwoByTwo = 1, ThreeByThree = 2 };

/// "single", "2x2", "3x3".
const char* toString(PcfMode mode);

/// The light that casts shadows: the scene's directional light 0 (orthographic
/// map) or its point light 0 (perspective map).
struct ShadowLight {
    bool perspective = false;           // false: directionalLights[0]; true: pointLights[0]
    glm::mat4 lightSpaceMatrix{1.0f};   // world -> the light's clip space
    float near = 0.1f;                  // world units; perspective maps, for the map view only
    float far = 50.0f;
    glm::vec3 sceneMin{-15.0f, 0.0f, -15.0f};   // world bounds of the casters, for the cascades' depth range
    glm::vec3 sceneMax{15.0f, 8.0f, 15.0f};
};

/// Cascaded shadow maps for the directional light (docs/labs/05_shadows.md,
/// "Cascaded shadow maps").
struct CascadeSettings {
    int count = 0;             // 0: one map (ShadowLight::lightSpaceMatrix); 1..kMaxCascades: cascades
    float lambda = 0.75f;      // the practical split's blend, 0 uniform .. 1 logarithmic
    float far = 80.0f;         // view depth where the last cascade ends, world units (capped by the camera's far)
    bool colors = false;       // tint each cascade (window key k)
};

struct ShadowSettings {
    bool enabled = true;                     // false: s = 1 everywhere, no depth pass
    PcfMode pcf = PcfMode::Single;
    glm::vec3 bias{0.004f, 0.0005f, 0.01f};  // (slope factor, minimum, maximum), window-depth units
    int mapSize = 1024;                      // texels per side
    bool showMap = false;                    // the map (or the cascades' maps) in the bottom-right corner
    CascadeSettings cascades;
};

class ShadowRenderer {
public:
    /// The three programs: shadows/depth.*, shadows/shadowed.*, shadows/depth_view.*.
    /// They must outlive the renderer. The passes call the student's functions
    /// (StudentCode::shadows; the cascade ones only when a case asks for
    /// cascades). Needs a current context.
    ShadowRenderer(const Program& depthProgram, const Program& shadowedProgram, const Program& mapViewProgram);

    /// Both passes (the first only when settings.enabled), into the framebuffer
    /// that is bound when called, over a viewport of `size` pixels.
    void render(const Scene& scene, const Camera& camera, glm::ivec2 size, const ShadowLight& light,
                const ShadowSettings& settings);

    /// The first pass alone (student code), then the framebuffer that was bound
    /// before is bound again. For timing and for render().
    void renderShadowMap(const Scene& scene, const ShadowLight& light, int mapSize);

    /// The second pass alone, reading the map of the last renderShadowMap().
    void renderLit(const Scene& scene, const Camera& camera, glm::ivec2 size, const ShadowLight& light,
                   const ShadowSettings& settings);

    /// The program for cascades: shadows/shadowed.vert + shadows/cascaded.frag,
    /// loaded only when a case asks for cascades (its stubs would make every
    /// case "not attempted"). Must outlive the renderer; nullptr: none yet.
    void setCascadeProgram(const Program* cascadeProgram) { m_cascadeProgram = cascadeProgram; }

    glm::vec3 clearColor{0.55f, 0.68f, 0.82f};   // a sky

    static constexpr int kMaxCascades = ShadowCascades::kMaxCascades;

private:
    static constexpr int kShadowMapUnit = 5;   // clear of the units materials use
    static constexpr int kFirstCascadeUnit = 6;   // kMaxCascades units from here

    /// Both passes with one map per slice of the camera's frustum.
    void renderCascaded(const Scene& scene, const Camera& camera, glm::ivec2 size, const ShadowLight& light,
                        const ShadowSettings& settings);
    static void afterStudentPass(GLuint target);
    void drawMapView(const Framebuffer& map, const ShadowLight& light, const glm::ivec4& rectangle);

    const Program& m_depthProgram;
    const Program& m_shadowedProgram;
    const Program& m_mapViewProgram;
    const Program* m_cascadeProgram = nullptr;
    Framebuffer m_shadowMap;
    ShadowCascades m_cascades;
    ForwardRenderer m_forward;
    TextureOverlay m_overlay;
};

} // namespace stoa
