// Lab 11's app: saving a scene file and the UI panels (scene, inspector,
// assets, shader, log, renderer settings) that stoa-editor shows.

#include "editor_app.hpp"

namespace stoa {

bool EditorLabApp::unsavedEdits() const {
    EditorScene now = m_scene;
    now.camera = m_savedCamera;
    try {
        return editorSceneToJson(now) != m_savedText;
    } catch (const std::exception&) {   // a position that is not a number cannot be saved: it is unsaved
        return true;
    }
}

void EditorLabApp::save() {
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
void EditorLabApp::drawRendererControls() {
    ImGui::SetNextWindowPos(ImVec2(370.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(355.0f, 0.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowCollapsed(!m_scene.renderer.deferred, ImGuiCond_FirstUseEver);
    const bool open = ImGui::Begin("Renderer");
    if (open) drawRendererSettings();
    ImGui::End();
}
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawRendererSettings() {
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
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawScenePanel() {
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
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::editVector(const char* label, glm::vec3 EditorObject::*member, float speed) {
    EditorObject* object = m_scene.findObject(m_selected);
    glm::vec3 value = object->*member;
    if (ImGui::DragFloat3(label, &value.x, speed)) recordEdit(label, *object, member, value);
    if (ImGui::IsItemDeactivatedAfterEdit()) m_history.endMerge();
}
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawLightInspector(const EditorLight& light) {
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
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawAgentInspector(const CrowdSimulation& crowd, std::size_t index) {
    const CrowdAgent& agent = crowd.agents()[index];
    const AgentType& type = crowd.world().types[static_cast<std::size_t>(agent.type)];
    ImGui::Text("agent %zu: %s (behaviour %s)", index, type.name.c_str(), type.behaviour.c_str());
    ImGui::Text("state %s, animation %s%s", crowd.stateName(index).c_str(), crowd.animationName(agent.animation).c_str(),
                agent.alive ? "" : ", waiting to respawn");
    ImGui::Text("at (%.2f, %.2f, %.2f), heading %.0f degrees", agent.position.x, agent.y, agent.position.y,
                glm::degrees(agent.heading));
    ImGui::Text("speed %.2f m/s, sight %.1f m", type.speed, type.sightRadius);
}
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawInspectorPanel() {
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
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawAssetPanel() {
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
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::spawn(const std::string& mesh) {
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
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawShaderPanel() {
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
#endif

#ifdef STOA_EDITOR_APP_IMGUI
void EditorLabApp::drawLogPanel() {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(350.0f, display.y - 120.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::max(200.0f, display.x - 360.0f), 110.0f), ImGuiCond_FirstUseEver);
    ImGui::Begin("Log");
    for (const std::string& line : m_log) ImGui::TextUnformatted(line.c_str());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
    ImGui::End();
}
#endif

} // namespace stoa
