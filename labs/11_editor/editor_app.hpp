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
inline EditorScene editorLabScene() {
    EditorScene scene;
    scene.ambient = glm::vec3(0.16f, 0.17f, 0.2f);
    scene.sunDirection = glm::vec3(-0.5f, -1.0f, -0.35f);
    scene.sunColor = glm::vec3(0.75f, 0.72f, 0.66f);
    const auto material = [&](const char* name, glm::vec3 diffuse, glm::vec3 specular, float shininess) {
        EditorMaterial m;
        m.name = name;
        m.diffuse = diffuse;
        m.specular = specular;
        m.shininess = shininess;
        scene.materials.push_back(m);
    };
    material("slate", {0.32f, 0.34f, 0.38f}, glm::vec3(0.05f), 8.0f);
    material("marble", {0.86f, 0.84f, 0.79f}, glm::vec3(0.3f), 48.0f);
    material("terracotta", {0.78f, 0.36f, 0.2f}, glm::vec3(0.1f), 16.0f);
    material("bronze", {0.55f, 0.38f, 0.18f}, glm::vec3(0.6f), 64.0f);
    material("gold", {0.92f, 0.72f, 0.2f}, glm::vec3(0.8f), 96.0f);
    material("teal", {0.16f, 0.58f, 0.56f}, glm::vec3(0.25f), 32.0f);
    material("panel", glm::vec3(1.0f), glm::vec3(0.1f), 16.0f);
    scene.materials.back().diffuseMap = "panel";   // the hot-reload asset (EditorLabApp::panelTexture)

    const auto object = [&](const char* name, const char* mesh, const char* materialName, glm::vec3 position,
                             glm::vec3 scale, glm::vec3 rotation = glm::vec3(0.0f)) {
        EditorObject& o = scene.addObject(name, mesh, materialName);
        o.position = position;
        o.scale = scale;
        o.rotationDegrees = rotation;
    };
    object("floor", "shape:plane", "slate", {0.0f, 0.0f, 0.0f}, {12.0f, 1.0f, 12.0f});
    object("column", "shape:cylinder", "marble", {-2.6f, 1.5f, 0.2f}, {0.7f, 3.0f, 0.7f});
    object("crate", "shape:cube", "terracotta", {0.4f, 0.5f, 0.9f}, glm::vec3(1.0f), {0.0f, 20.0f, 0.0f});
    object("ball", "shape:sphere", "bronze", {2.5f, 0.6f, -0.8f}, glm::vec3(1.2f));
    object("pole", "shape:cylinder", "gold", {1.9f, 1.0f, 1.9f}, {0.07f, 2.0f, 0.07f});
    object("panel", "shape:cube", "panel", {-0.4f, 1.1f, -2.4f}, {2.4f, 2.2f, 0.16f});

    EditorLight warm;
    warm.id = scene.nextId();
    warm.name = "warm lamp";
    warm.position = {-1.5f, 2.6f, 2.2f};
    warm.color = {1.3f, 0.9f, 0.55f};
    warm.radius = 7.0f;
    scene.lights.push_back(warm);
    EditorLight cool = warm;
    cool.id = scene.nextId();
    cool.name = "cool lamp";
    cool.position = {3.0f, 2.2f, 1.5f};
    cool.color = {0.4f, 0.6f, 1.1f};
    scene.lights.push_back(cool);
    return scene;
}

class EditorLabApp : public Lab {
public:
    static constexpr int kMaxObjects = 255;   // stencil values 1..255

    void initialize(LabResources& resources) override {
        resources.loadProgram("editor/lit.vert", "editor/lit.frag");   // listed for the app's stub check
        m_flatProgram = &resources.loadProgram("editor/flat.vert", "editor/flat.frag");
        m_imageProgram = &resources.loadProgram("basic/image.vert", "basic/image.frag");
        m_lineProgram = &resources.loadProgram("debug/lines.vert", "debug/lines.frag");
        m_flatProgram->bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
        m_overlay = std::make_unique<TextureOverlay>();
        m_frame = std::make_unique<FrameUniforms>();
        m_lines = std::make_unique<DebugLineRenderer>(*m_lineProgram);
        m_searchPath = resources.shaderSearchPath();   // for the deferred passes, loaded when first drawn
        m_assets = std::make_unique<EditorAssets>();
        m_assets->setReloadDispatch(assetsToReload);   // yours, for the files of a scene file's assets
    }

    void loadCase(const CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        m_view = spec.getChoice("view", {"shaded", "stencil"}, std::string("shaded")) == "stencil" ? View::Stencil
                                                                                                  : View::Shaded;
        m_pickRadius = spec.getIntInRange("pick_radius", 0, 8, 4);
        m_debounce = spec.getNumberInRange("debounce", 0.0, 2.0, 0.25);
        m_sceneFile.clear();
        if (spec.has("scene")) m_sceneFile = resolveScene(spec);
        m_script = spec.has("commands") ? parseCommands(spec) : std::vector<Command>{};
        m_scriptFrame = glm::vec2(spec.width, spec.height);
        m_scriptDone = false;
        reset();
    }

    void render(glm::ivec2 size) override {
        m_size = size;
        const Camera& camera = m_cameras.active();
        updateFrame(camera);
        if (!m_scriptDone) {
            m_scriptDone = true;
            runScript();
        }
        if (!m_sceneFile.empty()) reloadChangedAssets();
        if (soundInWindow) updateSound(camera);
        if (m_pipeline) {
            for (const glm::vec3& burst : m_pipeline->takeSparkBursts()) {   // lab 07's ball hit something
                char line[96];
                std::snprintf(line, sizeof line, "sparks at (%.2f, %.2f, %.2f)", burst.x, burst.y, burst.z);
                log(line);
                playSound(m_sparkSound, burst);
            }
        }
        if (m_view == View::Stencil) {
            drawStencilView();
            return;
        }
        drawShaded();
        drawSelection();
    }

    /// The window's clock: the crowd walks and the wandering lights wander
    /// (in the deferred pipeline); a headless picture stays at its start.
    void update(float seconds) override {
        if (m_pipeline && m_scene.renderer.deferred) m_pipeline->advance(seconds);
    }

    Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    CheckResult runCheck(const CaseSpec& spec) override {
        if (spec.check == "pick_within_a_circle") return lab11::checkPickWithinACircle();
        if (spec.check == "merge_rules") return lab11::checkMergeRules();
        if (spec.check == "reload_boundaries") return lab11::checkReloadBoundaries();
        return Lab::runCheck(spec);
    }

    bool keyPressed(unsigned char key) override {
        switch (key) {
        case 'u': log(m_history.undo(m_scene) ? "undo" : "nothing to undo"); return true;
        case 'r': log(m_history.redo(m_scene) ? "redo" : "nothing to redo"); return true;
        case 'm': {
            const EditorObject* object = m_scene.findObject(m_selected);
            if (!object) return false;
            auto it = std::find_if(m_scene.materials.begin(), m_scene.materials.end(),
                                   [&](const EditorMaterial& m) { return m.name == object->material; });
            const std::size_t next = it == m_scene.materials.end() ? 0 : (it - m_scene.materials.begin() + 1) % m_scene.materials.size();
            setMaterial(m_scene.materials[next].name);
            log(object->name + ": material " + m_scene.materials[next].name);
            return true;
        }
        case 'x': deleteSelection(); return true;
        case 'p': {   // the pipeline: forward (lab 11) or deferred (labs 04-10), an edit
            EditorRendererSettings settings = m_scene.renderer;
            settings.deferred = !settings.deferred;
            const EditorRendererSettings before = m_scene.renderer;
            m_history.perform(m_scene, {"renderer settings", [settings](EditorScene& s) { s.renderer = settings; },
                                        [before](EditorScene& s) { s.renderer = before; }, ""});
            log(settings.deferred ? "pipeline: deferred (labs 04-10)" : "pipeline: forward (lab 11)");
            return true;
        }
        case ',':
        case '.': {   // turn the selection 15 degrees about +Y, one edit each press
            const EditorObject* object = m_scene.findObject(m_selected);
            if (!object) return false;
            glm::vec3 rotation = object->rotationDegrees;
            rotation.y = std::fmod(rotation.y + (key == '.' ? 15.0f : -15.0f), 360.0f);
            recordEdit("rotation", *object, &EditorObject::rotationDegrees, rotation);
            m_history.endMerge();
            log(object->name + ": turned to " + std::to_string(static_cast<int>(std::lround(rotation.y))) + " degrees about y");
            return true;
        }
        case '-':
        case '=': {   // scale the selection by 1/1.1 or 1.1, one edit each press
            const EditorObject* object = m_scene.findObject(m_selected);
            if (!object) return false;
            const glm::vec3 scale = object->scale * (key == '=' ? 1.1f : 1.0f / 1.1f);
            recordEdit("scale", *object, &EditorObject::scale, scale);
            m_history.endMerge();
            char line[128];
            std::snprintf(line, sizeof line, "%s: scaled to (%.3f, %.3f, %.3f)", object->name.c_str(), scale.x, scale.y, scale.z);
            log(line);
            return true;
        }
        case 'b': {   // lab 07's ball, thrown from the eye along the view (deferred pipeline)
            if (!m_scene.renderer.deferred || !m_pipeline) {
                log("the ball (b) bounces in the deferred pipeline: switch it on in the renderer panel");
                return true;
            }
            const Camera& camera = m_cameras.active();
            try {
                m_pipeline->throwBall(m_scene, m_sceneFile.empty() ? paths::assetsDir() : m_sceneFile.parent_path(),
                                      camera.eyePosition(), camera.lookTarget() - camera.eyePosition());
                log("ball thrown");
            } catch (const NotImplemented& missing) {
                log("the ball needs " + missing.function() + " (" + missing.lab() + "), still a stub in this build");
            }
            return true;
        }
        case 'k':
            if (!m_sound || !m_sound->enabled()) return false;
            m_sound->setMuted(!m_sound->muted());
            log(m_sound->muted() ? "sound muted" : "sound on");
            return true;
        case 'v':
            m_view = m_view == View::Shaded ? View::Stencil : View::Shaded;
            std::printf("view: %s\n", m_view == View::Shaded ? "shaded" : "stencil");
            return true;
        default: return false;
        }
    }

    bool handleEvent(const InputEvent& event) override {
        // Ctrl+S: GLUT's control code 19 reaches keyPressed() as 's' (Window.cpp), so it is told here by Ctrl.
        if (event.type == InputEvent::Type::KeyDown && event.key == keyOf('s') && event.modifiers.control) {
            if (m_sceneFile.empty()) return false;
            save();
            return true;
        }
        if (event.button != MouseButton::Left && event.type != InputEvent::Type::MouseMove) return false;
        if (event.type == InputEvent::Type::MouseDown) {
            m_pressPixel = event.position;
            m_dragAxis = gizmoAxisNear(event.position);
            if (m_dragAxis < 0) return false;   // not on an arrow: the camera turns, or a click selects
            startDrag(event.position);
            return true;
        }
        if (event.type == InputEvent::Type::MouseMove && m_dragAxis >= 0) {
            dragTo(event.position);
            return true;
        }
        if (event.type == InputEvent::Type::MouseUp) {
            if (m_dragAxis >= 0) {
                m_history.endMerge();
                m_dragAxis = -1;
                if (const EditorObject* object = m_scene.findObject(m_selected)) {
                    std::printf("moved %s to (%.3f, %.3f, %.3f)\n", object->name.c_str(), object->position.x,
                                object->position.y, object->position.z);
                    std::fflush(stdout);
                }
                return true;
            }
            if (glm::length(event.position - m_pressPixel) < 3.0f) {   // a click, not a camera drag
                m_pendingClick = event.position;
                return true;
            }
        }
        return false;
    }

    bool uiPanelAtStart() const override { return !m_sceneFile.empty(); }

    /// Escape with unsaved edits to a scene file: a warning first, a second
    /// Escape quits without saving.
    bool quitRequested() override {
        if (m_sceneFile.empty() || m_quitWarned || !unsavedEdits()) return true;
        m_quitWarned = true;
        log("unsaved edits: Ctrl+S saves them; Escape again quits without saving");
        return false;
    }

    /// stoa-editor in a window: the wind loops, spawning and deleting make a
    /// sound where it happens, a crowd's agents make footsteps (deferred
    /// pipeline), and the listener follows the camera (k mutes).
    bool soundInWindow = false;
    /// The deferred pipeline waits for each pass to finish, so that its
    /// statistics hold each pass's own time (the showcase benchmark).
    bool timePasses = false;
    /// The deferred pipeline; nullptr before its first frame.
    const EditorPipeline* pipeline() const { return m_pipeline.get(); }

    void drawUi() override {
#ifdef STOA_EDITOR_APP_IMGUI
        ImGui::Text("%s", m_sceneFile.empty() ? "lab 11's scene" : m_sceneFile.filename().string().c_str());
        ImGui::Text("%zu objects, %zu lights; %zu edits to undo, %zu to redo", m_scene.objects.size(), m_scene.lights.size(),
                    m_history.undoCount(), m_history.redoCount());
        if (ImGui::Button("Undo (u)")) keyPressed('u');
        ImGui::SameLine();
        if (ImGui::Button("Redo (r)")) keyPressed('r');
        if (!m_sceneFile.empty()) {
            ImGui::SameLine();
            if (ImGui::Button("Save (Ctrl+S)")) save();
        }
        if (m_sound && m_sound->enabled()) {
            bool muted = m_sound->muted();
            if (ImGui::Checkbox("mute (k)", &muted)) keyPressed('k');
        }
        bool stencil = m_view == View::Stencil;
        if (ImGui::Checkbox("show the stencil pick pass (v)", &stencil)) m_view = stencil ? View::Stencil : View::Shaded;
        drawRendererControls();
        drawScenePanel();
        drawInspectorPanel();
        drawAssetPanel();
        drawShaderPanel();
        drawLogPanel();
#endif
    }

    std::vector<std::string> keyHelp() const override {
        return {"click        select the object under the mouse (stencil pick)",
                "drag arrow   move the selection along the gizmo's x, y or z arrow",
                "u / r        undo / redo",
                "m / x        next material for the selection / delete it",
                ", / .        turn the selection 15 degrees about y (one edit each)",
                "p            pipeline: forward (lab 11) / deferred (labs 04-10), an edit",
                "- / =        scale the selection by 1/1.1 / 1.1 (one edit each)",
                "b            throw a ball (deferred pipeline: lab 07's BVH bounce, sparks)",
                "v            switch view: shaded / the stencil pick pass",
                "Ctrl+S       save the scene file (stoa-editor)"};
    }

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
    bool unsavedEdits() const {
        EditorScene now = m_scene;
        now.camera = m_savedCamera;
        try {
            return editorSceneToJson(now) != m_savedText;
        } catch (const std::exception&) {   // a position that is not a number cannot be saved: it is unsaved
            return true;
        }
    }

    void save() {
        const OrbitCamera& orbit = m_cameras.orbit;
        m_scene.camera = {orbit.lookTarget(), orbit.distance(), orbit.yawDegrees(), orbit.pitchDegrees()};
        m_savedCamera = m_scene.camera;
        try {
            saveEditorScene(m_scene, m_sceneFile);
            m_savedText = editorSceneToJson(m_scene);
            m_quitWarned = false;
            log("saved " + m_sceneFile.string());
        } catch (const std::exception& error) {
            log(std::string("not saved: ") + error.what());
        }
    }

#ifdef STOA_EDITOR_APP_IMGUI
    /// The scene's renderer settings (an edit each) and what the last frame drew.
    /// A panel of its own between the Stoa panel and the asset browser, open at
    /// the start where the scene asks for the deferred pipeline (the showcase).
    void drawRendererControls() {
        ImGui::SetNextWindowPos(ImVec2(370.0f, 10.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(355.0f, 0.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowCollapsed(!m_scene.renderer.deferred, ImGuiCond_FirstUseEver);
        const bool open = ImGui::Begin("Renderer");
        if (open) drawRendererSettings();
        ImGui::End();
    }

    void drawRendererSettings() {
        EditorRendererSettings settings = m_scene.renderer;
        int pipeline = settings.deferred ? 1 : 0;
        bool changed = ImGui::RadioButton("forward (lab 11)", &pipeline, 0);
        ImGui::SameLine();
        changed |= ImGui::RadioButton("deferred (labs 04-10)", &pipeline, 1);
        settings.deferred = pipeline == 1;
        if (settings.deferred) {
            changed |= ImGui::Checkbox("shadows (lab 05)", &settings.shadows);
            ImGui::SameLine();
            static const char* filters[] = {"one tap", "2x2", "3x3"};
            ImGui::SetNextItemWidth(80.0f);
            if (ImGui::BeginCombo("PCF", filters[std::min(std::max(settings.pcfSize, 1), 3) - 1])) {
                for (int i = 0; i < 3; ++i)
                    if (ImGui::Selectable(filters[i], settings.pcfSize == i + 1)) {
                        settings.pcfSize = i + 1;
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            changed |= ImGui::Checkbox("normal maps (lab 04)", &settings.normalMaps);
            ImGui::SameLine();
            changed |= ImGui::Checkbox("sky (lab 06)", &settings.sky);
            changed |= ImGui::Checkbox("ambient occlusion (lab 09)", &settings.ssao);
            changed |= ImGui::Checkbox("culling and levels of detail (lab 06)", &settings.culling);
            if (ImGui::BeginCombo("view", settings.debugView.c_str())) {
                for (const std::string& view : courseViewNames())
                    if (ImGui::Selectable(view.c_str(), settings.debugView == view)) {
                        settings.debugView = view;
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            if (m_pipeline) {
                const CourseStats& stats = m_pipeline->stats();
                ImGui::Text("%d objects: %d culled, %d too small", stats.objects, stats.culled, stats.tooSmall);
                ImGui::Text("drawn by level of detail: %d / %d / %d / %d", stats.perLevel[0], stats.perLevel[1],
                            stats.perLevel[2], stats.perLevel[3]);
                ImGui::Text("%d lights (%ld in tiles), %d agents, %.0f ms", stats.pointLights, stats.tileListEntries,
                            stats.agents, 1e3 * stats.totalSeconds);
            }
        }
        if (!changed) return;
        const EditorRendererSettings before = m_scene.renderer;
        m_history.perform(m_scene, {"renderer settings", [settings](EditorScene& s) { s.renderer = settings; },
                                    [before](EditorScene& s) { s.renderer = before; }, ""});
    }

    /// Every object and light; a click selects.
    void drawScenePanel() {
        ImGui::SetNextWindowPos(ImVec2(10.0f, 230.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(200.0f, 190.0f), ImGuiCond_FirstUseEver);
        ImGui::Begin("Scene");
        for (const EditorObject& object : m_scene.objects) {
            ImGui::PushID(static_cast<int>(object.id));
            if (ImGui::Selectable(object.name.c_str(), object.id == m_selected)) m_selected = object.id;
            ImGui::PopID();
        }
        ImGui::Separator();
        for (const EditorLight& light : m_scene.lights) {
            ImGui::PushID(static_cast<int>(light.id));
            bool on = light.on;
            if (ImGui::Checkbox("##on", &on)) {
                const std::uint32_t id = light.id;
                m_history.perform(m_scene, {std::string(on ? "switch on " : "switch off ") + light.name,
                                            [id, on](EditorScene& s) { if (EditorLight* l = s.findLight(id)) l->on = on; },
                                            [id, on](EditorScene& s) { if (EditorLight* l = s.findLight(id)) l->on = !on; }, ""});
            }
            ImGui::SameLine();
            if (ImGui::Selectable(light.name.c_str(), light.id == m_selected)) m_selected = light.id;   // the inspector edits it
            ImGui::PopID();
        }
        if (const CrowdSimulation* crowd = m_pipeline && m_scene.renderer.deferred ? m_pipeline->crowd() : nullptr) {
            ImGui::Separator();
            if (ImGui::TreeNode("crowd", "crowd: %zu agents", crowd->agents().size())) {
                for (std::size_t i = 0; i < crowd->agents().size(); ++i) {
                    const CrowdAgent& agent = crowd->agents()[i];
                    const std::string label = std::to_string(i) + ": " + crowd->world().types[static_cast<std::size_t>(agent.type)].name;
                    if (ImGui::Selectable(label.c_str(), static_cast<int>(i) == m_selectedAgent)) {
                        m_selectedAgent = static_cast<int>(i);
                        m_selected = 0;
                    }
                }
                ImGui::TreePop();
            }
        }
        ImGui::End();
    }

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
    void editVector(const char* label, glm::vec3 EditorObject::*member, float speed) {
        EditorObject* object = m_scene.findObject(m_selected);
        glm::vec3 value = object->*member;
        if (ImGui::DragFloat3(label, &value.x, speed)) recordEdit(label, *object, member, value);
        if (ImGui::IsItemDeactivatedAfterEdit()) m_history.endMerge();
    }

    /// The selected light's position, colour (with its intensity: components
    /// may pass 1) and radius, each drag one undo step.
    void drawLightInspector(const EditorLight& light) {
        ImGui::Text("%s (id %u, point light)", light.name.c_str(), light.id);
        glm::vec3 position = light.position;
        if (ImGui::DragFloat3("position", &position.x, 0.02f)) recordEdit("position", light, &EditorLight::position, position);
        if (ImGui::IsItemDeactivatedAfterEdit()) m_history.endMerge();
        glm::vec3 color = light.color;
        if (ImGui::ColorEdit3("colour", &color.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR))
            recordEdit("colour", light, &EditorLight::color, glm::max(color, glm::vec3(0.0f)));
        if (ImGui::IsItemDeactivatedAfterEdit()) m_history.endMerge();
        float radius = light.radius;
        if (ImGui::DragFloat("radius", &radius, 0.05f, 0.1f, 100.0f, "%.2f m"))
            recordEdit("radius", light, &EditorLight::radius, std::max(radius, 0.1f));
        if (ImGui::IsItemDeactivatedAfterEdit()) m_history.endMerge();
    }

    /// A crowd agent, read-only: lab 10's simulation decides what it does.
    void drawAgentInspector(const CrowdSimulation& crowd, std::size_t index) {
        const CrowdAgent& agent = crowd.agents()[index];
        const AgentType& type = crowd.world().types[static_cast<std::size_t>(agent.type)];
        ImGui::Text("agent %zu: %s (behaviour %s)", index, type.name.c_str(), type.behaviour.c_str());
        ImGui::Text("state %s, animation %s%s", crowd.stateName(index).c_str(), agent.animation.c_str(),
                    agent.alive ? "" : ", waiting to respawn");
        ImGui::Text("at (%.2f, %.2f, %.2f), heading %.0f degrees", agent.position.x, agent.y, agent.position.y,
                    glm::degrees(agent.heading));
        ImGui::Text("speed %.2f m/s, sight %.1f m", type.speed, type.sightRadius);
    }

    void drawInspectorPanel() {
        ImGui::SetNextWindowPos(ImVec2(10.0f, 430.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(330.0f, 150.0f), ImGuiCond_FirstUseEver);
        ImGui::Begin("Inspector");
        EditorObject* object = m_scene.findObject(m_selected);
        const CrowdSimulation* crowd = m_pipeline && m_scene.renderer.deferred ? m_pipeline->crowd() : nullptr;
        if (const EditorLight* light = m_scene.findLight(m_selected)) {
            drawLightInspector(*light);
        } else if (!object && crowd && m_selectedAgent >= 0 && m_selectedAgent < static_cast<int>(crowd->agents().size())) {
            drawAgentInspector(*crowd, static_cast<std::size_t>(m_selectedAgent));
        } else if (!object) {
            ImGui::TextDisabled("nothing selected: click an object");
        } else {
            ImGui::Text("%s (id %u, %s)", object->name.c_str(), object->id, object->mesh.c_str());
            editVector("position", &EditorObject::position, 0.02f);
            editVector("rotation", &EditorObject::rotationDegrees, 0.5f);
            editVector("scale", &EditorObject::scale, 0.01f);
            if (ImGui::BeginCombo("material", object->material.c_str())) {
                for (const EditorMaterial& material : m_scene.materials)
                    if (ImGui::Selectable(material.name.c_str(), material.name == object->material)) setMaterial(material.name);
                ImGui::EndCombo();
            }
            if (ImGui::Button("Delete (x)")) deleteSelection();
        }
        ImGui::End();
    }

    /// Shapes and models: spawn one at the camera's target.
    void drawAssetPanel() {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(display.x - 230.0f, 10.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(220.0f, 200.0f), ImGuiCond_FirstUseEver);
        ImGui::Begin("Assets");
        ImGui::TextDisabled("click to spawn at the view's centre");
        if (m_modelNames.empty()) {
            m_modelNames = EditorAssets::shapeNames();
            for (const std::string& name : m_assets->modelNames()) m_modelNames.push_back(name);
        }
        for (const std::string& name : m_modelNames)
            if (ImGui::Selectable(name.c_str())) spawn(name);
        ImGui::End();
    }

    void spawn(const std::string& mesh) {
        if (m_scene.objects.size() >= static_cast<std::size_t>(kMaxObjects)) {
            log("not spawned: the stencil pick tells at most 255 objects apart");
            return;
        }
        EditorObject object;
        object.id = m_scene.nextId();
        object.name = mesh.substr(mesh.find_last_of(":/") + 1) + " " + std::to_string(object.id);
        object.mesh = mesh;
        object.material = m_scene.materials.empty() ? std::string() : m_scene.materials.front().name;
        object.position = m_cameras.orbit.lookTarget();
        if (m_scene.materials.empty()) {
            log("not spawned: the scene has no material to give it");
            return;
        }
        playSound(m_sparkSound, object.position);
        m_history.perform(m_scene, {"spawn " + object.name, [object](EditorScene& s) { s.objects.push_back(object); },
                                    [id = object.id](EditorScene& s) { s.removeObject(id); }, ""});
        m_selected = object.id;
    }

    /// The selection's material's fragment shader, recompiled as you type;
    /// an error shows at its line and the last good program keeps drawing.
    /// Until the first edit the panel shows the file (reloaded with it); from
    /// then on the editor draws with the panel's text until "Back to the file".
    void drawShaderPanel() {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(display.x - 470.0f, 220.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(460.0f, std::max(200.0f, display.y - 350.0f)), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);   // open it with its arrow
        if (!ImGui::Begin("Shader")) {
            ImGui::End();
            return;
        }
        const EditorObject* object = m_scene.findObject(m_selected);
        const EditorMaterial* material = object ? m_scene.findMaterial(object->material) : nullptr;
        const std::string name = material && !material->shader.empty() ? material->shader : EditorAssets::kDefaultProgram;
        ImGui::Text("%s.frag%s", name.c_str(), object ? "" : " (select an object for its material's)");
        try {
            const bool live = m_assets->hasLiveShader(name);
            const int version = m_assets->programVersion(name);
            if (m_shaderName != name || (!live && version != m_shaderFileVersion)) {
                m_shaderName = name;
                m_shaderFileVersion = version;
                m_shaderText = live ? m_assets->liveShader(name).fragmentText() : EditorAssets::fragmentFileText(name);
                m_shaderEdited.reset();
            }
            if (ImGui::InputTextMultiline("##glsl", &m_shaderText, ImVec2(-1.0f, -60.0f), ImGuiInputTextFlags_AllowTabInput))
                m_shaderEdited = std::chrono::steady_clock::now();
            if (m_shaderEdited && std::chrono::steady_clock::now() - *m_shaderEdited > std::chrono::milliseconds(300)) {
                m_shaderEdited.reset();
                LiveShader& shader = m_assets->liveShader(name);
                if (shader.setFragmentText(m_shaderText)) log("shader " + name + ": compiled");
                else log("shader " + name + ": " + shader.error());
            }
            if (!m_assets->hasLiveShader(name)) {
                ImGui::TextDisabled("the file's text: type to edit it live");
            } else {
                LiveShader& shader = m_assets->liveShader(name);
                if (!shader.error().empty()) {
                    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "line %d: %s", shader.errorLine(), shader.error().c_str());
                    ImGui::TextDisabled("drawing with the last program that compiled");
                } else if (ImGui::Button("Save to file")) {
                    try {
                        shader.saveToFile();
                        log("saved " + shader.fragmentFile().string());
                    } catch (const std::exception& error) {
                        log(std::string("not saved: ") + error.what());
                    }
                }
                ImGui::SameLine();
                if (ImGui::Button("Back to the file")) {
                    m_assets->dropLiveShader(name);
                    m_shaderName.clear();   // the file's text again at the next frame
                    log("shader " + name + ": drawing with its file again");
                }
            }
        } catch (const std::exception& error) {
            ImGui::TextWrapped("cannot edit %s: %s", name.c_str(), error.what());
        }
        ImGui::End();
    }

    void drawLogPanel() {
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        ImGui::SetNextWindowPos(ImVec2(350.0f, display.y - 120.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSize(ImVec2(std::max(200.0f, display.x - 360.0f), 110.0f), ImGuiCond_FirstUseEver);
        ImGui::Begin("Log");
        for (const std::string& line : m_log) ImGui::TextUnformatted(line.c_str());
        if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
        ImGui::End();
    }
#endif

    // --- the script ------------------------------------------------------------

    std::vector<Command> parseCommands(const CaseSpec& spec) const {
        std::vector<Command> commands;
        std::stringstream all(spec.getString("commands"));
        std::string text;
        while (std::getline(all, text, ';')) {
            text.erase(0, text.find_first_not_of(" \t"));
            text.erase(text.find_last_not_of(" \t") + 1);
            std::istringstream words(text);
            std::string verb;
            if (!(words >> verb)) continue;
            Command command;
            const auto bad = [&](const std::string& expected) {
                spec.reject("commands", "in '" + text + "': " + expected);
            };
            const auto pixel = [&](glm::vec2& p) {
                if (!(words >> p.x >> p.y)) bad("expected a pixel x y");
                if (p.x < 0 || p.y < 0 || p.x >= spec.width || p.y >= spec.height)
                    bad("the pixel lies outside the " + std::to_string(spec.width) + " x " + std::to_string(spec.height) + " picture");
            };
            if (verb == "select") {
                command.kind = Command::Kind::Select;
                pixel(command.from);
            } else if (verb == "drag") {
                command.kind = Command::Kind::Drag;
                std::string axis;
                words >> axis;
                if (axis != "x" && axis != "y" && axis != "z") bad("drag needs an axis x, y or z, then two pixels");
                command.axis = axis[0] - 'x';
                pixel(command.from);
                pixel(command.to);
            } else if (verb == "material") {
                command.kind = Command::Kind::Material;
                if (!(words >> command.name)) bad("material needs a material's name");
                if (!editorLabScene().findMaterial(command.name)) bad("no material '" + command.name + "'");
            } else if (verb == "delete" || verb == "undo" || verb == "redo") {
                command.kind = verb == "delete" ? Command::Kind::Delete : verb == "undo" ? Command::Kind::Undo : Command::Kind::Redo;
            } else if (verb == "save") {
                command.kind = Command::Kind::Save;
                std::string at;
                if (!(words >> command.name >> at >> command.seconds) || at != "at" ||
                    (command.name != "diffuse" && command.name != "stripes") || !(command.seconds >= 0.0 && command.seconds <= 60.0))
                    bad("expected 'save diffuse at T' or 'save stripes at T', T in [0, 60] seconds");
            } else if (verb == "tick") {
                command.kind = Command::Kind::Tick;
                if (!(words >> command.seconds) || !(command.seconds >= 0.0 && command.seconds <= 60.0))
                    bad("tick needs a time in [0, 60] seconds");
            } else {
                bad("unknown command '" + verb + "' (select, drag, material, delete, undo, redo, save, tick)");
            }
            std::string extra;
            if (words >> extra) bad("unexpected '" + extra + "' at the end");
            commands.push_back(command);
        }
        return commands;
    }

    void runScript() {
        const glm::vec2 toWindow = glm::vec2(m_size) / m_scriptFrame;
        for (const Command& command : m_script) {
            switch (command.kind) {
            case Command::Kind::Select: select(command.from * toWindow); break;
            case Command::Kind::Drag: {
                if (!m_scene.findObject(m_selected)) break;
                m_dragAxis = command.axis;
                startDrag(command.from * toWindow);
                for (int step = 1; step <= 4; ++step)
                    dragTo(glm::mix(command.from, command.to, step / 4.0f) * toWindow);
                m_history.endMerge();
                m_dragAxis = -1;
                break;
            }
            case Command::Kind::Material: setMaterial(command.name); break;
            case Command::Kind::Delete: deleteSelection(); break;
            case Command::Kind::Undo: m_history.undo(m_scene); break;
            case Command::Kind::Redo: m_history.redo(m_scene); break;
            case Command::Kind::Save: saveFile(command.name, command.seconds); break;
            case Command::Kind::Tick: tick(command.seconds); break;
            }
        }
    }

    // --- edits -------------------------------------------------------------------

    std::filesystem::path resolveScene(const CaseSpec& spec) const {
        const std::string name = spec.getString("scene");
        std::error_code error;
        for (const std::filesystem::path& candidate :
             {std::filesystem::path(name), std::filesystem::path(spec.file).parent_path() / name, paths::assetsDir() / "scenes" / name})
            if (std::filesystem::is_regular_file(candidate, error)) return std::filesystem::absolute(candidate).lexically_normal();
        spec.reject("scene", "no scene file '" + name + "' (looked as given, next to the cases file and in " +
                                 (paths::assetsDir() / "scenes").string() + ")");
        return {};
    }

    void reset() {
        m_scene = m_sceneFile.empty() ? editorLabScene() : loadEditorScene(m_sceneFile);
        m_savedText = m_sceneFile.empty() ? std::string() : editorSceneToJson(m_scene);
        m_savedCamera = m_scene.camera;
        m_quitWarned = false;
        if (m_assets) m_assets->setSceneFolder(m_sceneFile.empty() ? paths::assetsDir() : m_sceneFile.parent_path());
        m_history = EditHistory();
        m_selected = 0;
        m_selectedAgent = -1;
        m_dragAxis = -1;
        m_pendingClick.reset();
        m_fileVersions = {{"diffuse", 0}, {"stripes", 0}};
        m_changes.clear();
        m_panelFiles = {0, 0};
        m_panelLoadedAt = -1.0;   // loaded before the clock starts at 0
        m_panelTexture.reset();
    }

    void select(glm::vec2 pixel) {
        const StencilReadback stencil = drawPickPass();
        const int index = objectAtPixel(stencil, glm::ivec2(pixel), m_pickRadius);
        m_selected = index >= 0 && index < static_cast<int>(m_scene.objects.size()) ? m_scene.objects[index].id : 0;
        const EditorObject* object = m_scene.findObject(m_selected);
        log(object ? "selected " + object->name : "selected nothing");
    }

    void setMaterial(const std::string& name) {
        const EditorObject* object = m_scene.findObject(m_selected);
        if (!object) return;
        const std::uint32_t id = object->id;
        const std::string before = object->material;
        m_history.perform(m_scene, {"material of " + object->name,
                                    [id, name](EditorScene& s) { if (EditorObject* o = s.findObject(id)) o->material = name; },
                                    [id, before](EditorScene& s) { if (EditorObject* o = s.findObject(id)) o->material = before; },
                                    ""});
    }

    void deleteSelection() {
        const auto it = std::find_if(m_scene.objects.begin(), m_scene.objects.end(),
                                     [&](const EditorObject& o) { return o.id == m_selected; });
        if (it == m_scene.objects.end()) return;
        const EditorObject copy = *it;
        playSound(m_sparkSound, copy.position);
        const std::size_t index = static_cast<std::size_t>(it - m_scene.objects.begin());
        m_history.perform(m_scene, {"delete " + copy.name, [id = copy.id](EditorScene& s) { s.removeObject(id); },
                                    [copy, index](EditorScene& s) {
                                        s.objects.insert(s.objects.begin() + static_cast<long>(std::min(index, s.objects.size())), copy);
                                    },
                                    ""});
        m_selected = 0;
    }

    void startDrag(glm::vec2 pixel) {
        const EditorObject* object = m_scene.findObject(m_selected);
        if (!object) return;
        m_dragStart = object->position;
        m_pressRay = rayThrough(pixel);
    }

    void dragTo(glm::vec2 pixel) {
        const EditorObject* object = m_scene.findObject(m_selected);
        if (!object) return;
        glm::vec3 axis(0.0f);
        axis[m_dragAxis] = 1.0f;
        const glm::vec3 to = dragAlongAxis(m_dragStart, axis, m_pressRay, rayThrough(pixel));
        const glm::vec3 from = object->position;
        const std::uint32_t id = object->id;
        m_history.perform(m_scene, {"move " + object->name,
                                    [id, to](EditorScene& s) { if (EditorObject* o = s.findObject(id)) o->position = to; },
                                    [id, from](EditorScene& s) { if (EditorObject* o = s.findObject(id)) o->position = from; },
                                    "move " + std::to_string(id)});
    }

    // --- hot reload ----------------------------------------------------------------
    // The panel's texture is built from two files, its diffuse colours and its
    // stripes; each save writes a new version of one. The files are simulated so
    // that pictures do not depend on the file system's clock; stoa-editor watches
    // real files (AssetCache).

    static std::string panelFile(const std::string& name) { return "/lab11/panel_" + name + ".png"; }

    void saveFile(const std::string& name, double seconds) {
        ++m_fileVersions[name];
        m_changes.push_back({panelFile(name), seconds});
    }

    void tick(double now) {
        const std::vector<AssetFiles> assets = {{"panel", {panelFile("diffuse"), panelFile("stripes")}, m_panelLoadedAt}};
        for (const std::string& name : assetsToReload(m_changes, assets, now, m_debounce)) {
            if (name != "panel") continue;
            m_panelFiles = {m_fileVersions["diffuse"], m_fileVersions["stripes"]};
            m_panelLoadedAt = now;
            m_panelTexture.reset();
            char line[96];
            std::snprintf(line, sizeof line, "reloaded panel at %.2f s (diffuse v%d, stripes v%d)", now, m_panelFiles[0], m_panelFiles[1]);
            log(line);
        }
    }

    const Texture2D& panelTexture() {
        if (!m_panelTexture) {
            static const glm::vec3 colours[] = {{0.9f, 0.85f, 0.7f}, {0.3f, 0.55f, 0.9f}, {0.9f, 0.3f, 0.35f}, {0.35f, 0.8f, 0.4f}};
            const glm::vec3 paper = colours[m_panelFiles[0] % 4];
            const int stripes = 2 + 2 * (m_panelFiles[1] % 4);
            m_panelTexture = std::make_unique<Texture2D>(pictureTexture({64, 64}, [&](int x, int) {
                const bool ink = ((x * stripes) / 64) % 2 == 1;
                return ink ? paper * 0.35f : paper;
            }));
        }
        return *m_panelTexture;
    }

    /// A scene file's textures, models and programs: reloaded when their files
    /// change (your assetsToReload() decides when), the log printed.
    void reloadChangedAssets() {
        const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started).count();
        m_assets->update(now);
        for (const std::string& line : m_assets->takeLog()) log(line);
    }

    void updateSound(const Camera& camera) {
        if (!m_sound) {
            m_sound = std::make_unique<SoundDevice>();   // sound off, with one line, where there is no device
            if (!m_sound->enabled()) return;
            try {
                const auto clip = [](const char* name) { return SoundClip::fromFile(paths::assetsDir() / "sounds" / name).mono(); };
                m_sparkSound = m_sound->upload(clip("spark.ogg"));
                m_footstepSound = m_sound->upload(clip("footstep.ogg"));
                m_sound->playAmbient(m_sound->upload(clip("ambient_wind.ogg")), 0.25f);
            } catch (const std::exception& error) {
                log(std::string("sound: ") + error.what());
            }
        }
        m_sound->setListener(camera.eyePosition(), camera.lookTarget() - camera.eyePosition(), camera.upVector());
        if (m_pipeline) {
            // The crowd's footsteps (deferred pipeline): the nearest few of each frame, so that twenty
            // walkers do not take every source.
            std::vector<glm::vec3> steps = m_pipeline->takeFootsteps();
            const glm::vec3 ear = camera.eyePosition();
            std::sort(steps.begin(), steps.end(), [&](const glm::vec3& a, const glm::vec3& b) {
                return glm::length(a - ear) < glm::length(b - ear);
            });
            for (std::size_t i = 0; i < steps.size() && i < 3; ++i)
                if (glm::length(steps[i] - ear) < 40.0f && m_footstepSound.id != 0) m_sound->play(m_footstepSound, steps[i], 0.5f);
        }
        m_sound->update();
    }

    void playSound(SoundBuffer buffer, const glm::vec3& where) {
        if (m_sound && m_sound->enabled() && buffer.id != 0) m_sound->play(buffer, where, 0.8f);
    }

    void log(const std::string& line) {
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
        m_log.push_back(line);
        if (m_log.size() > 200) m_log.erase(m_log.begin());
    }

    // --- drawing -------------------------------------------------------------------

    void updateFrame(const Camera& camera) {
        Scene lights;
        lights.ambient = m_scene.ambient;
        lights.directionalLights = {DirectionalLight{m_scene.sunDirection, m_scene.sunColor}};
        lights.pointLights = pointLights();
        m_aspect = static_cast<float>(m_size.x) / static_cast<float>(m_size.y);
        m_frame->update(camera, m_aspect, lights);
        m_frame->bind();
        m_viewProjection = camera.projectionMatrix(m_aspect) * camera.viewMatrix();
    }

    glm::mat4 modelOf(const EditorObject& object) const {
        return modelMatrix(object.position, object.rotationDegrees, object.scale);
    }

    void drawMeshes(const EditorObject& object) {
        for (const GpuMesh* mesh : m_assets->meshes(object.mesh)) mesh->draw();
    }

    /// The pick pass: each object drawn with stencil value index + 1 over 0,
    /// colour writes off, into a target of the window's size; read back.
    StencilReadback drawPickPass() {
        if (!m_pickTarget || m_pickTarget->width() != m_size.x || m_pickTarget->height() != m_size.y)
            m_pickTarget = std::make_unique<Framebuffer>(m_size.x, m_size.y);
        const GLuint previous = StateCache::current().drawFramebuffer();
        PassDescription pass = passInto(*m_pickTarget);
        pass.state.colorMask = {false, false, false, false};
        pass.state.stencil.test = true;
        pass.state.stencil.pass = GL_REPLACE;
        pass.clear.depth = pass.clear.stencil = true;
        beginPass(pass);
        m_flatProgram->use();
        const std::size_t count = std::min<std::size_t>(m_scene.objects.size(), kMaxObjects);
        for (std::size_t i = 0; i < count; ++i) {
            RenderState state = pass.state;
            state.stencil.ref = static_cast<int>(i + 1);
            StateCache::current().apply(state);
            m_flatProgram->set("uModel", modelOf(m_scene.objects[i]));
            drawMeshes(m_scene.objects[i]);
        }
        StencilReadback readback;
        readback.width = m_size.x;
        readback.height = m_size.y;
        readback.values.resize(static_cast<std::size_t>(m_size.x) * m_size.y);
        m_pickTarget->readPixels(-1, 0, 0, m_size.x, m_size.y, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, readback.values.data());
        StateCache::current().bindFramebuffer(previous);
        return readback;
    }

    void drawShaded() {
        if (m_pendingClick) {   // a click in the window: pick now that the frame's camera is set
            select(*m_pendingClick);
            m_pendingClick.reset();
        }
        if (m_scene.renderer.deferred) {
            drawDeferred();
            return;
        }
        PassDescription pass = passInto(m_size);
        pass.clear.color = pass.clear.depth = pass.clear.stencil = true;
        pass.clear.colorValue = glm::vec4(0.09f, 0.1f, 0.13f, 1.0f);
        pass.state.cull = CullMode::None;
        beginPass(pass);
        for (const EditorObject& object : m_scene.objects) {
            const EditorMaterial* found = m_scene.findMaterial(object.material);
            const Material material = materialOf(found);
            const Program& program = m_assets->program(found ? found->shader : std::string());
            program.use();
            // Locations per program; a reloaded or re-edited program is a new GL program.
            auto& [programId, uniforms] = m_objectUniforms[&program];
            if (!uniforms || programId != program.id()) {
                uniforms = std::make_unique<ObjectUniforms>(program);
                programId = program.id();
            }
            DrawItem item = drawItemOf(object, found, material);
            for (const GpuMesh* mesh : m_assets->meshes(object.mesh)) {
                item.mesh = mesh;
                uniforms->apply(item);
                mesh->draw();
            }
        }
    }

    /// The draw-time material of a scene material (the default one for none).
    static Material materialOf(const EditorMaterial* found) {
        Material material;
        if (found) {
            material.ambient = material.diffuse = found->diffuse;
            material.specular = found->specular;
            material.shininess = found->shininess;
        }
        return material;
    }

    /// An object's draw item without its mesh: matrices, `material`, diffuse map.
    DrawItem drawItemOf(const EditorObject& object, const EditorMaterial* found, const Material& material) {
        DrawItem item;
        item.model = modelOf(object);
        item.normalMatrix = glm::inverseTranspose(glm::mat3(item.model));
        item.material = &material;
        if (found && !found->diffuseMap.empty())
            item.diffuseMap = m_sceneFile.empty() && found->diffuseMap == "panel" ? &panelTexture() : m_assets->texture(found->diffuseMap);
        return item;
    }

    /// The scene's point lights that are on; the attenuation reaches about 1/76
    /// of the light at its radius (constant 1, linear 4.5 / r, quadratic 75 / r^2).
    std::vector<PointLight> pointLights() const {
        std::vector<PointLight> lights;
        for (const EditorLight& light : m_scene.lights) {
            if (!light.on) continue;
            PointLight point;
            point.position = light.position;
            point.color = light.color;
            point.attenuation = glm::vec3(1.0f, 4.5f / light.radius, 75.0f / (light.radius * light.radius));
            lights.push_back(point);
        }
        return lights;
    }

    /// The deferred pipeline: every lab's pass in one frame (editor_pipeline.hpp,
    /// stoa/render/CourseRenderer.hpp) with the students' code of labs 04-10,
    /// loaded at the first deferred frame. A lab's function that is still a
    /// stub switches the pipeline off with a line in the log.
    void drawDeferred() {
        if (!m_pipeline) {
            m_pipeline = std::make_unique<EditorPipeline>(m_searchPath, [this](const std::string& line) { log(line); });
            // Lab 04's tangents on every mesh from now on, for the normal maps
            // (the forward pass, and so every graded case, does without).
            m_assets->setMeshFilter([this](Mesh& mesh) {
                if (m_tangentsMissing) return;
                try {
                    computeTangents(mesh);
                } catch (const NotImplemented& missing) {
                    m_tangentsMissing = true;
                    log("normal maps off: " + missing.function() + " (" + missing.lab() + ") is still a stub in this build");
                }
            });
        }
        const GLuint output = StateCache::current().drawFramebuffer();
        try {
            m_pipeline->prepare(m_scene, m_sceneFile.empty() ? paths::assetsDir() : m_sceneFile.parent_path(), *m_assets);
            // The objects, with materials and maps that live as long as the frame.
            m_drawMaterials.assign(m_scene.objects.size() + 1, Material());
            std::vector<CourseItem> items;
            for (std::size_t i = 0; i < m_scene.objects.size(); ++i) {
                const EditorObject& object = m_scene.objects[i];
                const EditorMaterial* found = m_scene.findMaterial(object.material);
                m_drawMaterials[i] = materialOf(found);
                const DrawItem drawn = drawItemOf(object, found, m_drawMaterials[i]);
                CourseItem item;
                item.id = object.id;   // the "ids" view shows the scene's own ids
                item.model = drawn.model;
                item.normalMatrix = drawn.normalMatrix;
                item.material = &m_drawMaterials[i];
                item.diffuseMap = drawn.diffuseMap;
                item.normalMap = found && !m_tangentsMissing ? normalMap(found->normalMap) : nullptr;
                for (const GpuMesh* mesh : m_assets->meshes(object.mesh)) {
                    item.levels = {mesh};
                    item.sphere = transformed(mesh->bounds(), item.model).sphere;   // culled, one level
                    items.push_back(item);
                }
            }
            const EditorMaterial* fieldFound = m_scene.findMaterial(m_scene.field.material);
            m_drawMaterials.back() = materialOf(fieldFound);
            const Texture2D* fieldDiffuse = fieldFound ? m_assets->texture(fieldFound->diffuseMap) : nullptr;

            const EditorRendererSettings& renderer = m_scene.renderer;
            CourseSettings settings;
            settings.culling = renderer.culling;
            settings.shadows = renderer.shadows;
            settings.pcf = renderer.pcfSize == 1 ? PcfMode::Single : renderer.pcfSize == 2 ? PcfMode::TwoByTwo
                                                                                             : PcfMode::ThreeByThree;
            settings.normalMaps = renderer.normalMaps && !m_tangentsMissing;
            settings.ambientOcclusion = renderer.ssao;
            settings.sky = renderer.sky;
            if (!courseViewFromName(renderer.debugView, settings.view)) settings.view = CourseView::Final;
            settings.timePasses = timePasses;
            m_pipeline->selectAgent(m_selected == 0 ? m_selectedAgent : -1);
            m_pipeline->render(m_scene, std::move(items), pointLights(), &m_drawMaterials.back(), fieldDiffuse,
                               m_cameras.active(), m_size, settings);
        } catch (const NotImplemented& missing) {
            log("the deferred pipeline needs " + missing.function() + " (" + missing.lab() +
                "), still a stub in this build: drawing forward");
            m_scene.renderer.deferred = false;
            StateCache::current().bindFramebuffer(output);
            drawShaded();
            return;
        }
        StateCache::current().bindFramebuffer(output);
        m_frame->bind();   // the deferred passes bind their own frame block
        PassDescription clearStencil = passInto(m_size);
        clearStencil.clear.stencil = true;
        beginPass(clearStencil);
    }

    /// A material's normal map: a tangent-space map as it is, or a height map
    /// (.pgm) turned into one by lab 04's normalMapFromHeight(), once per name.
    const Texture2D* normalMap(const std::string& name) {
        if (name.empty()) return nullptr;
        const auto extension = std::filesystem::path(name).extension();
        if (extension != ".pgm") return m_assets->texture(name);
        auto found = m_heightNormalMaps.find(name);
        if (found != m_heightNormalMaps.end()) return found->second.get();
        std::unique_ptr<Texture2D>& texture = m_heightNormalMaps[name];
        std::error_code error;
        std::filesystem::path path = (m_sceneFile.empty() ? paths::assetsDir() : m_sceneFile.parent_path()) / name;
        if (!std::filesystem::is_regular_file(path, error)) path = paths::assetsDir() / name;
        try {
            texture = std::make_unique<Texture2D>(Texture2D::fromImage(normalMapFromHeight(loadHeightMap(path), 6.0f)));
        } catch (const InputError& bad) {
            log(std::string("cannot use the normal map ") + name + ": " + bad.what());
        } catch (const NotImplemented& missing) {
            m_tangentsMissing = true;
            log("normal maps off: " + missing.function() + " (" + missing.lab() + ") is still a stub in this build");
        }
        return texture.get();
    }

    /// The selection: its outline (the object a little larger, drawn where the
    /// stencil does not hold it) and its gizmo's three arrows.
    void drawSelection() {
        const EditorObject* object = m_scene.findObject(m_selected);
        if (!object) return;
        RenderState mark;
        mark.cull = CullMode::None;
        mark.colorMask = {false, false, false, false};
        mark.depth.test = false;
        mark.stencil.test = true;
        mark.stencil.ref = 1;
        mark.stencil.pass = GL_REPLACE;
        beginPass(passInto(m_size, mark));
        m_flatProgram->use();
        m_flatProgram->set("uModel", modelOf(*object));
        drawMeshes(*object);

        RenderState outline = RenderState::overlay();
        outline.stencil.test = true;
        outline.stencil.func = GL_NOTEQUAL;
        outline.stencil.ref = 1;
        beginPass(passInto(m_size, outline));
        // 0.06 world units wider along each of the object's axes (its meshes are 1 unit across).
        const glm::vec3 grow = glm::vec3(1.0f) + glm::min(glm::vec3(0.06f) / glm::max(glm::abs(object->scale), glm::vec3(1e-3f)),
                                                          glm::vec3(2.0f));
        m_flatProgram->set("uModel", modelOf(*object) * glm::scale(glm::mat4(1.0f), grow));
        m_flatProgram->set("uColor", glm::vec3(1.0f, 0.62f, 0.1f));
        drawMeshes(*object);

        DebugLines arrows;
        const float length = gizmoLength(*object);
        const glm::vec3 colours[3] = {{0.95f, 0.2f, 0.2f}, {0.3f, 0.9f, 0.3f}, {0.25f, 0.45f, 1.0f}};
        for (int axis = 0; axis < 3; ++axis) {
            glm::vec3 direction(0.0f);
            direction[axis] = 1.0f;
            arrows.line(object->position, object->position + direction * length, colours[axis]);
        }
        beginPass(passInto(m_size, RenderState::overlay()));
        m_lines->draw(arrows, m_viewProjection);
    }

    void drawStencilView() {
        const StencilReadback stencil = drawPickPass();
        int selectedValue = -1;   // drawn white
        for (std::size_t i = 0; i < m_scene.objects.size(); ++i)
            if (m_scene.objects[i].id == m_selected) selectedValue = static_cast<int>(i + 1);
        const Texture2D picture = pictureTexture(m_size, [&](int x, int y) {
            const std::uint8_t value = stencil.values[static_cast<std::size_t>(m_size.y - 1 - y) * m_size.x + x];
            if (value == selectedValue) return glm::vec3(1.0f);
            if (value == 0) return glm::vec3(0.0f);
            // Neighbouring values far apart in hue: value * golden angle.
            const float hue = std::fmod(value * 0.618034f, 1.0f) * 6.0f;
            return glm::clamp(glm::abs(glm::mod(hue + glm::vec3(0.0f, 4.0f, 2.0f), 6.0f) - 3.0f) - 1.0f, 0.0f, 1.0f);
        });
        picture.bind(0);
        m_imageProgram->set("uImage", 0);
        m_overlay->draw(*m_imageProgram, {0, 0, m_size.x, m_size.y});
    }

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
    Line rayThrough(glm::vec2 pixel) const {
        const glm::mat4 inverse = glm::inverse(m_viewProjection);
        const glm::vec2 ndc((pixel.x + 0.5f) / m_size.x * 2.0f - 1.0f, 1.0f - (pixel.y + 0.5f) / m_size.y * 2.0f);
        const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
        const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
        const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w;
        const glm::vec3 b = glm::vec3(farPoint) / farPoint.w;
        return {a, b - a};
    }

    float gizmoLength(const EditorObject& object) const {
        return 0.6f + 0.5f * std::max(object.scale.x, std::max(object.scale.y, object.scale.z)) * (object.mesh == "shape:plane" ? 0.0f : 1.0f);
    }

    glm::vec2 toPixel(const glm::vec3& world) const {
        const glm::vec4 clip = m_viewProjection * glm::vec4(world, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return {(ndc.x + 1.0f) * 0.5f * m_size.x, (1.0f - ndc.y) * 0.5f * m_size.y};
    }

    /// The gizmo arrow within 10 pixels of `pixel` (0 x, 1 y, 2 z), or -1.
    int gizmoAxisNear(glm::vec2 pixel) const {
        const EditorObject* object = m_scene.findObject(m_selected);
        if (!object) return -1;
        int best = -1;
        float bestDistance = 10.0f;
        const glm::vec2 a = toPixel(object->position);
        for (int axis = 0; axis < 3; ++axis) {
            glm::vec3 direction(0.0f);
            direction[axis] = 1.0f;
            const glm::vec2 b = toPixel(object->position + direction * gizmoLength(*object));
            const glm::vec2 ab = b - a;
            const float t = glm::clamp(glm::dot(pixel - a, ab) / std::max(1e-6f, glm::dot(ab, ab)), 0.25f, 1.0f);
            const float distance = glm::length(pixel - (a + t * ab));
            if (distance < bestDistance) {
                bestDistance = distance;
                best = axis;
            }
        }
        return best;
    }

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
