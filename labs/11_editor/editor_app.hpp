#pragma once
// Lab 11's app: a small scene edited by a script of editor commands, the way a
// user would with the mouse and keys, then drawn with the selection outlined
// and its move gizmo. Every command goes through your code: a click picks
// through the stencil buffer (objectAtPixel, stencil_pick.cpp), a drag moves
// along an axis (dragAlongAxis, gizmo.cpp), every edit is a command in your
// EditHistory (history.cpp), and the panel's texture reloads when your
// assetsToReload() (hot_reload.cpp) says so. Not a student file.
//
// Case keys besides the camera's (CameraRig.hpp):
//   commands = C; C; ...   editor commands, run in order before the picture:
//       select X Y              a click at pixel (X, Y) of the picture (from the top-left)
//       drag AXIS X0 Y0 X1 Y1   the selection dragged along x, y or z from pixel
//                               (X0, Y0) to (X1, Y1), in 4 mouse moves (one edit)
//       material NAME           the selection's material becomes NAME
//       delete                  the selection is deleted
//       undo | redo             your EditHistory's undo() and redo()
//       save FILE at T          the panel's file FILE (diffuse or stripes) saved at T seconds
//       tick T                  the editor's clock at T seconds: your assetsToReload() decides
//   view = shaded | stencil     stencil: the pick pass's values in false colour (default shaded)
//   pick_radius = n             pixels a click may miss a thin object by, 0..8 (default 4)
//   debounce = seconds          the hot-reload quiet time, [0, 2] (default 0.25)
// In the window: a click selects, a drag on an arrow of the gizmo moves the
// selection along it, u undoes, r redoes, m gives the selection the next
// material, x deletes it, v switches the view.

#include "lab01.hpp"
#include "lab04.hpp"
#include "lab11.hpp"
#include "checks.hpp"
#include "editor_pipeline.hpp"

#include <stoa/audio/SoundClip.hpp>
#include <stoa/audio/SoundDevice.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/editor/EditorAssets.hpp>
#include <stoa/editor/EditorSceneFile.hpp>
#include <stoa/geometry/DebugLines.hpp>
#include <stoa/geometry/Material.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/Lab.hpp>
#include <stoa/render/AmbientOcclusion.hpp>
#include <stoa/render/AmbientOcclusionPass.hpp>
#include <stoa/render/DebugLineRenderer.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/render/TextureOverlay.hpp>
#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/ObjectUniforms.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#if __has_include(<imgui.h>)
#include <imgui.h>
#include <imgui_stdlib.h>
#define STOA_EDITOR_APP_IMGUI 1
#endif

namespace stoa {

/// The scene lab 11 edits: a floor, a column, a crate, a bronze ball, a thin
/// golden pole (hard to click) and a panel whose texture the hot-reload cases
/// rewrite, under the sun and two point lights.
EditorScene editorLabScene();

class EditorLabApp : public Lab {
public:
    static constexpr int kMaxObjects = 255;   // stencil values 1..255

    void initialize(LabResources& resources) override;

    void loadCase(const CaseSpec& spec) override;

    void render(glm::ivec2 size) override;

    /// The window's clock: the crowd walks and the wandering lights wander
    /// (in the deferred pipeline); a headless picture stays at its start.
    void update(float seconds) override;

    Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    CheckResult runCheck(const CaseSpec& spec) override;

    bool keyPressed(unsigned char key) override;

    bool handleEvent(const InputEvent& event) override;

    bool uiPanelAtStart() const override { return !m_sceneFile.empty(); }

    /// Escape with unsaved edits to a scene file: a warning first, a second
    /// Escape quits without saving.
    bool quitRequested() override;

    /// stoa-editor in a window: the wind loops, spawning and deleting make a
    /// sound where it happens, a crowd's agents make footsteps (deferred
    /// pipeline), and the listener follows the camera (k mutes).
    bool soundInWindow = false;
    /// A picture made from the command line (--render, --screenshot) stops at an
    /// asset the scene names that does not load, naming the scene file's line:
    /// a picture with a piece missing is not the scene.
    bool stopOnMissingAssets = false;
    /// The deferred pipeline waits for each pass to finish, so that its
    /// statistics hold each pass's own time (the showcase benchmark).
    bool timePasses = false;
    /// The deferred pipeline; nullptr before its first frame.
    const EditorPipeline* pipeline() const { return m_pipeline.get(); }

    void drawUi() override;

    std::vector<std::string> keyHelp() const override;

    const EditorScene& scene() const { return m_scene; }
    const EditHistory& history() const { return m_history; }

private:
    enum class View { Shaded, Stencil };

    struct Command {
        enum class Kind { Select, Drag, Material, Delete, Undo, Redo, Save, Tick } kind = Kind::Select;
        glm::vec2 from{0.0f}, to{0.0f};
        int axis = 0;
        std::string name;
        double seconds = 0.0;
    };

    // --- saving and the panels (stoa-editor) -----------------------------------------

    /// Whether the scene differs from the file as last loaded or saved (the camera aside).
    bool unsavedEdits() const;

    void save();

#ifdef STOA_EDITOR_APP_IMGUI
    /// The scene's renderer settings (an edit each) and what the last frame drew.
    /// A panel of its own between the Stoa panel and the asset browser, open at
    /// the start where the scene asks for the deferred pipeline (the showcase).
    void drawRendererControls();

    void drawRendererSettings();

    /// Every object and light; a click selects.
    void drawScenePanel();

    static EditorObject* findThing(EditorScene& scene, std::uint32_t id, EditorObject*) { return scene.findObject(id); }
    static EditorLight* findThing(EditorScene& scene, std::uint32_t id, EditorLight*) { return scene.findLight(id); }

    /// One field of an object or a light set to `value` as an edit: successive
    /// changes of the same field merge into one undo step until endMerge().
    template <typename Thing, typename Value>
    void recordEdit(const std::string& label, const Thing& thing, Value Thing::*member, const Value& value) {
        const std::uint32_t id = thing.id;
        const Value before = thing.*member;
        m_history.perform(m_scene, {label + " of " + thing.name,
                                    [id, member, value](EditorScene& s) {
                                        if (Thing* t = findThing(s, id, static_cast<Thing*>(nullptr))) t->*member = value;
                                    },
                                    [id, member, before](EditorScene& s) {
                                        if (Thing* t = findThing(s, id, static_cast<Thing*>(nullptr))) t->*member = before;
                                    },
                                    label + " " + std::to_string(id)});
    }

    /// A vec3 of the selection edited by dragging: one undo step per drag.
    void editVector(const char* label, glm::vec3 EditorObject::*member, float speed);

    /// The selected light's position, colour (with its intensity: components
    /// may pass 1) and radius, each drag one undo step.
    void drawLightInspector(const EditorLight& light);

    /// A crowd agent, read-only: lab 10's simulation decides what it does.
    void drawAgentInspector(const CrowdSimulation& crowd, std::size_t index);

    void drawInspectorPanel();

    /// Shapes and models: spawn one at the camera's target.
    void drawAssetPanel();

    void spawn(const std::string& mesh);

    /// The selection's material's fragment shader, recompiled as you type;
    /// an error shows at its line and the last good program keeps drawing.
    /// Until the first edit the panel shows the file (reloaded with it); from
    /// then on the editor draws with the panel's text until "Back to the file".
    void drawShaderPanel();

    void drawLogPanel();
#endif

    // --- the script ------------------------------------------------------------

    std::vector<Command> parseCommands(const CaseSpec& spec) const;

    void runScript();

    // --- edits -------------------------------------------------------------------

    std::filesystem::path resolveScene(const CaseSpec& spec) const;

    void reset();

    void select(glm::vec2 pixel);

    void setMaterial(const std::string& name);

    void deleteSelection();

    void startDrag(glm::vec2 pixel);

    void dragTo(glm::vec2 pixel);

    // --- hot reload ----------------------------------------------------------------
    // The panel's texture is built from two files, its diffuse colours and its
    // stripes; each save writes a new version of one. The files are simulated so
    // that pictures do not depend on the file system's clock; stoa-editor watches
    // real files (AssetCache).

    static std::string panelFile(const std::string& name) { return "/lab11/panel_" + name + ".png"; }

    void saveFile(const std::string& name, double seconds);

    void tick(double now);

    const Texture2D& panelTexture();

    /// A scene file's textures, models and programs: reloaded when their files
    /// change (your assetsToReload() decides when), the log printed.
    void reloadChangedAssets();
    /// stopOnMissingAssets: an InputError at the scene file's line that names the asset.
    [[noreturn]] void throwMissingAsset(const EditorAssets::Failure& failure) const;

    void updateSound(const Camera& camera);

    void playSound(SoundBuffer buffer, const glm::vec3& where);

    void log(const std::string& line);

    // --- drawing -------------------------------------------------------------------

    void updateFrame(const Camera& camera);

    glm::mat4 modelOf(const EditorObject& object) const;

    void drawMeshes(const EditorObject& object);

    /// The pick pass: each object drawn with stencil value index + 1 over 0,
    /// colour writes off, into a target of the window's size; read back.
    StencilReadback drawPickPass();

    void drawShaded();

    /// The draw-time material of a scene material (the default one for none).
    static Material materialOf(const EditorMaterial* found);

    /// An object's draw item without its mesh: matrices, `material`, diffuse map.
    DrawItem drawItemOf(const EditorObject& object, const EditorMaterial* found, const Material& material);

    /// The scene's point lights that are on; the attenuation reaches about 1/76
    /// of the light at its radius (constant 1, linear 4.5 / r, quadratic 75 / r^2).
    std::vector<PointLight> pointLights() const;

    /// The deferred pipeline: every lab's pass in one frame (editor_pipeline.hpp,
    /// stoa/render/CourseRenderer.hpp) with the students' code of labs 04-10,
    /// loaded at the first deferred frame. A lab's function that is still a
    /// stub switches the pipeline off with a line in the log.
    void drawDeferred();

    /// A material's normal map: a tangent-space map as it is, or a height map
    /// (.pgm) turned into one by lab 04's normalMapFromHeight(), once per name.
    const Texture2D* normalMap(const std::string& name);

    /// The selection: its outline (the object a little larger, drawn where the
    /// stencil does not hold it) and its gizmo's three arrows.
    void drawSelection();

    void drawStencilView();

    /// A texture of `size` texels, `colour(x, y)` from the top-left corner, sampled nearest.
    template <typename Colour>
    static Texture2D pictureTexture(glm::ivec2 size, Colour colour) {
        Image image(size.x, size.y, 4);
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::vec3 c = glm::clamp(colour(x, y), 0.0f, 1.0f);
                std::uint8_t* p = image.data() + (static_cast<std::size_t>(y) * size.x + x) * 4;
                p[0] = static_cast<std::uint8_t>(c.r * 255.0f);
                p[1] = static_cast<std::uint8_t>(c.g * 255.0f);
                p[2] = static_cast<std::uint8_t>(c.b * 255.0f);
                p[3] = 255;
            }
        TextureOptions options;
        options.mipmaps = false;
        options.linear = false;
        return Texture2D::fromImage(image, options);
    }

    // --- the mouse -------------------------------------------------------------------

    /// The mouse ray through `pixel` (window pixels from the top-left corner).
    Line rayThrough(glm::vec2 pixel) const;

    float gizmoLength(const EditorObject& object) const;

    glm::vec2 toPixel(const glm::vec3& world) const;

    /// The gizmo arrow within 10 pixels of `pixel` (0 x, 1 y, 2 z), or -1.
    int gizmoAxisNear(glm::vec2 pixel) const;

    CameraRig m_cameras;
    EditorScene m_scene = editorLabScene();
    EditHistory m_history;
    std::uint32_t m_selected = 0;
    View m_view = View::Shaded;
    int m_pickRadius = 4;
    double m_debounce = 0.25;
    std::vector<Command> m_script;
    glm::vec2 m_scriptFrame{1.0f};
    bool m_scriptDone = false;

    int m_dragAxis = -1;
    glm::vec3 m_dragStart{0.0f};
    Line m_pressRay;
    glm::vec2 m_pressPixel{0.0f};
    std::optional<glm::vec2> m_pendingClick;

    std::map<std::string, int> m_fileVersions;
    std::vector<FileChange> m_changes;
    std::array<int, 2> m_panelFiles{0, 0};
    double m_panelLoadedAt = -1.0;
    std::unique_ptr<Texture2D> m_panelTexture;

    glm::ivec2 m_size{1};
    float m_aspect = 1.0f;
    glm::mat4 m_viewProjection{1.0f};
    const Program* m_flatProgram = nullptr;
    const Program* m_imageProgram = nullptr;
    const Program* m_lineProgram = nullptr;
    std::map<const Program*, std::pair<GLuint, std::unique_ptr<ObjectUniforms>>> m_objectUniforms;
    std::unique_ptr<EditorAssets> m_assets;
    std::filesystem::path m_sceneFile;   // empty: the lab's scene
    std::vector<std::string> m_log;      // the latest lines, for the log panel
    std::string m_savedText;             // the scene as last loaded or saved, as JSON
    EditorCamera m_savedCamera;          // its camera (moving the camera is no edit)
    bool m_quitWarned = false;           // Escape said "unsaved edits" once
    std::vector<std::string> m_modelNames;   // the asset panel's list
    std::unique_ptr<SoundDevice> m_sound;    // made at the first frame of soundInWindow
    SoundBuffer m_sparkSound;
    SoundBuffer m_footstepSound;
    std::string m_shaderName;                // the shader panel's program and text
    std::string m_shaderText;
    int m_shaderFileVersion = 0;             // the file's program version m_shaderText was read at
    std::optional<std::chrono::steady_clock::time_point> m_shaderEdited;   // last keystroke not compiled yet
    std::chrono::steady_clock::time_point m_started = std::chrono::steady_clock::now();
    std::unique_ptr<FrameUniforms> m_frame;
    std::unique_ptr<DebugLineRenderer> m_lines;
    std::unique_ptr<Framebuffer> m_pickTarget;
    std::unique_ptr<TextureOverlay> m_overlay;
    std::vector<std::filesystem::path> m_searchPath;                 // the lab's GLSL search path
    std::vector<std::unique_ptr<Program>> m_deferredPrograms;        // labs 08 and 09's passes
    std::unique_ptr<EditorPipeline> m_pipeline;                      // labs 04-10's passes, made when first drawn
    std::vector<Material> m_drawMaterials;                           // the deferred items'
    std::map<std::string, std::unique_ptr<Texture2D>> m_heightNormalMaps;   // normal maps made from height maps
    bool m_tangentsMissing = false;                                  // lab 04's computeTangents() is a stub
    int m_selectedAgent = -1;                                        // the crowd's agent the inspector shows
};

} // namespace stoa
