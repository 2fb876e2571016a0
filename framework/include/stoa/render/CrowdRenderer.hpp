#pragma once
// Draws a CrowdSimulation (lab 10, stoa-crowds): the ground (the Acropolis or
// the height map's terrain), every agent as its MD2 model in its current pose,
// one instanced draw per agent type, all lit by the sun and shadowed through
// one shadow map over the footprint; then, on request, the agents' trails, the
// samples, the crumbs and the bases.
//
// The pose is blended on the GPU (shaders/crowd/md2.vert): every frame of a
// model waits in a buffer texture, and each instance says which two frames and
// how far between them, from the student's md2FramesAt(). Drawing one agent
// alone on the CPU with blendMd2Frames() is posePicture()'s job (the lab's close view).
//
//   CrowdRenderer renderer(programs, simulation);        // needs a current context
//   renderer.render(simulation, view, size, options);

#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/geometry/Md2Model.hpp>
#include <stoa/gl/BufferTexture.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/render/DebugLineRenderer.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/render/InstancedMesh.hpp>
#include <stoa/scene/PieceDrawList.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace stoa {

class Program;

/// The programs, loaded by the caller (a lab through its LabResources).
struct CrowdPrograms {
    const Program* scenery = nullptr;     // crowd/static.vert + crowd/lit.frag
    const Program* agents = nullptr;      // crowd/md2.vert + crowd/lit.frag
    const Program* sceneryDepth = nullptr;// crowd/static.vert + crowd/depth.frag
    const Program* agentsDepth = nullptr; // crowd/md2.vert + crowd/depth.frag
    const Program* markers = nullptr;     // instanced/instanced.vert + instanced/instanced.frag
    const Program* lines = nullptr;       // debug/lines.vert + debug/lines.frag

    using Loader = std::function<const Program&(const std::string& vertex, const std::string& fragment)>;
    static CrowdPrograms load(const Loader& load);
};

/// Where the picture is seen from: view and projection matrices, and the eye.
struct CrowdView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 eye{0.0f, 10.0f, 0.0f};

    /// Straight down over the footprint, +x to the right and +z down the
    /// picture (the maps' orientation), the whole footprint in view for `aspect`.
    static CrowdView topDown(const GroundGrid& footprint, float aspect);
};

struct CrowdDrawOptions {
    bool trails = false;
    bool markers = true;          // samples, crumbs, bases
    bool shadows = true;
    /// The scenery in its textures' mean colours (the top view: a texture
    /// shrunk 15 times is filtered differently by every driver, and averaged
    /// it reads the same).
    bool flatScenery = false;
    float framesPerSecond = 8.0f; // of the MD2 animations
    int selected = -1;            // this agent drawn highlighted
    glm::vec3 sunDirection{-0.45f, -1.0f, -0.35f};   // towards the ground
    glm::vec3 sunColor{0.85f, 0.8f, 0.72f};
    glm::vec3 ambient{0.36f, 0.38f, 0.44f};
    glm::vec3 sky{0.62f, 0.72f, 0.85f};
};

/// An agent type's model on the GPU: its frames for md2.vert, its corners, its skin.
struct Md2GpuModel {
    Md2Model model;
    std::unique_ptr<InstancedMesh> corners;   // one vertex per triangle corner: x = the MD2 vertex, uv
    BufferTexture frames;                      // per frame, per vertex: (position, 1), (normal, 0)
    Texture2D skin;
    float scale = 1.0f;
};

/// The model with its frames uploaded and its skin loaded. Throws InputError
/// naming the file when the MD2 or the skin is broken.
std::unique_ptr<Md2GpuModel> uploadMd2(const std::filesystem::path& model, const std::filesystem::path& skin, float scale);

/// A mesh of the pose between two frames, one vertex per triangle corner,
/// from the student's blendMd2Frames() (through `code`).
Mesh md2PoseMesh(const Md2Model& model, const Md2FramePair& frames, const CrowdFunctions& code);

class CrowdRenderer {
public:
    /// Uploads the ground and scenery of the simulation's world and every
    /// agent type's model. Needs a current context; the programs must outlive it.
    CrowdRenderer(const CrowdPrograms& programs, const CrowdSimulation& simulation);
    ~CrowdRenderer();

    /// Draws into the framebuffer bound now, over `size` pixels.
    void render(const CrowdSimulation& simulation, const CrowdView& view, glm::ivec2 size,
                const CrowdDrawOptions& options);

    /// The model of agent type i.
    /// The agents alone, drawn with `program` (crowd/md2.vert with a fragment
    /// stage of the caller's: the course pipeline's G-buffer and shadow passes)
    /// into the framebuffer bound now, under the frame block bound now.
    void drawAgentsWith(const CrowdSimulation& simulation, const Program& program, const CrowdDrawOptions& options);
    /// The world's markers (samples, crumbs, bases; trails with options.trails)
    /// into the framebuffer bound now, in the render state applied now, lit by
    /// the frame block bound now (the course pipeline draws them into its light
    /// buffer, depth-tested against the G-buffer's depth).
    void drawMarkersWith(const CrowdSimulation& simulation, const CrowdView& view, const CrowdDrawOptions& options) {
        drawMarkers(simulation, view, options);
    }
    const Md2GpuModel& model(std::size_t type) const { return *m_models[type]; }

    /// The frame block of `view`, lit by `options`' sun and ambient light (for callers that draw more).
    static FrameBlock frameBlock(const CrowdView& view, const CrowdDrawOptions& options);

private:
    void renderShadowMap(const CrowdDrawOptions& options);
    void drawScenery(const Program& program, bool depthOnly, bool flat = false);
    /// Each agent's instance (its matrix, and its two frames from the lab's
    /// md2FramesAt()), per type; once a frame, for the shadow and the lit pass.
    void uploadAgents(const CrowdSimulation& simulation, const CrowdDrawOptions& options);
    void drawAgents(const Program& program);
    void drawMarkers(const CrowdSimulation& simulation, const CrowdView& view, const CrowdDrawOptions& options);

    CrowdPrograms m_programs;
    FrameUniforms m_frame;
    std::vector<std::unique_ptr<Md2GpuModel>> m_models;
    std::unique_ptr<PieceDrawList> m_acropolis;
    std::vector<glm::vec3> m_flatColours;   // per acropolis item: its diffuse colour times its texture's mean
    std::unique_ptr<GpuMesh> m_terrain;
    Material m_terrainMaterial;
    Framebuffer m_shadowMap;
    glm::mat4 m_lightSpace{1.0f};
    std::unique_ptr<InstancedMesh> m_sampleMesh;
    std::unique_ptr<InstancedMesh> m_crumbMesh;
    std::unique_ptr<InstancedMesh> m_baseMesh;
    DebugLineRenderer m_lines;
    glm::vec3 m_sceneMin{0.0f}, m_sceneMax{1.0f};
};

} // namespace stoa
