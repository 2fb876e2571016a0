// Lab 11's app: its scene, the Lab interface (cases, frames, keys, events,
// the UI panel) and the checks. The class is declared in editor_app.hpp.

#include "editor_app.hpp"

namespace stoa {

EditorScene editorLabScene() {
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

void EditorLabApp::initialize(LabResources& resources) {
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

void EditorLabApp::loadCase(const CaseSpec& spec) {
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

void EditorLabApp::render(glm::ivec2 size) {
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
    } else {
        drawShaded();
        drawSelection();
    }
    if (stopOnMissingAssets && !m_assets->failures().empty()) throwMissingAsset(m_assets->failures().front());
}

void EditorLabApp::update(float seconds) {
    if (m_pipeline && m_scene.renderer.deferred) m_pipeline->advance(seconds);
}

CheckResult EditorLabApp::runCheck(const CaseSpec& spec) {
    if (spec.check == "pick_within_a_circle") return lab11::checkPickWithinACircle();
    if (spec.check == "merge_rules") return lab11::checkMergeRules();
    if (spec.check == "reload_boundaries") return lab11::checkReloadBoundaries();
    return Lab::runCheck(spec);
}

bool EditorLabApp::keyPressed(unsigned char key) {
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
        log(m_view == View::Shaded ? "view: shaded" : "view: stencil");
        return true;
    default: return false;
    }
}

bool EditorLabApp::handleEvent(const InputEvent& event) {
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
                char line[200];
                std::snprintf(line, sizeof line, "moved %s to (%.3f, %.3f, %.3f)", object->name.c_str(),
                              object->position.x, object->position.y, object->position.z);
                log(line);
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

bool EditorLabApp::quitRequested() {
    if (m_sceneFile.empty() || m_quitWarned || !unsavedEdits()) return true;
    m_quitWarned = true;
    log("unsaved edits: Ctrl+S saves them; Escape again quits without saving");
    return false;
}

void EditorLabApp::drawUi() {
#ifdef STOA_EDITOR_APP_IMGUI
    ImGui::Text("%s", m_sceneFile.empty() ? "lab 11's scene" : m_sceneFile.filename().string().c_str());
    const auto counted = [](std::size_t n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    ImGui::Text("%s, %s; %s to undo, %zu to redo", counted(m_scene.objects.size(), "object", "objects").c_str(),
                counted(m_scene.lights.size(), "light", "lights").c_str(),
                counted(m_history.undoCount(), "edit", "edits").c_str(), m_history.redoCount());
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

std::vector<std::string> EditorLabApp::keyHelp() const {
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

} // namespace stoa
