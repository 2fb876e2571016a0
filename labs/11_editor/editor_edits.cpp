// Lab 11's app: the case's command script, the edits it and the mouse make
// (select, drag, material, delete), and the mouse's rays and gizmo arrows.

#include "editor_app.hpp"

namespace stoa {

std::vector<EditorLabApp::Command> EditorLabApp::parseCommands(const CaseSpec& spec) const {
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

void EditorLabApp::runScript() {
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

std::filesystem::path EditorLabApp::resolveScene(const CaseSpec& spec) const {
    const std::string name = spec.getString("scene");
    std::error_code error;
    for (const std::filesystem::path& candidate :
         {std::filesystem::path(name), std::filesystem::path(spec.file).parent_path() / name, paths::assetsDir() / "scenes" / name})
        if (std::filesystem::is_regular_file(candidate, error)) return std::filesystem::absolute(candidate).lexically_normal();
    spec.reject("scene", "no scene file '" + name + "' (looked as given, next to the cases file and in " +
                             (paths::assetsDir() / "scenes").string() + ")");
    return {};
}

void EditorLabApp::reset() {
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

void EditorLabApp::select(glm::vec2 pixel) {
    const StencilReadback stencil = drawPickPass();
    const int index = objectAtPixel(stencil, glm::ivec2(pixel), m_pickRadius);
    m_selected = index >= 0 && index < static_cast<int>(m_scene.objects.size()) ? m_scene.objects[index].id : 0;
    const EditorObject* object = m_scene.findObject(m_selected);
    log(object ? "selected " + object->name : "selected nothing");
}

void EditorLabApp::setMaterial(const std::string& name) {
    const EditorObject* object = m_scene.findObject(m_selected);
    if (!object) return;
    const std::uint32_t id = object->id;
    const std::string before = object->material;
    m_history.perform(m_scene, {"material of " + object->name,
                                [id, name](EditorScene& s) { if (EditorObject* o = s.findObject(id)) o->material = name; },
                                [id, before](EditorScene& s) { if (EditorObject* o = s.findObject(id)) o->material = before; },
                                ""});
}

void EditorLabApp::deleteSelection() {
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
    log("deleted " + copy.name + " (u undoes it)");
}

void EditorLabApp::startDrag(glm::vec2 pixel) {
    const EditorObject* object = m_scene.findObject(m_selected);
    if (!object) return;
    m_dragStart = object->position;
    m_pressRay = rayThrough(pixel);
}

void EditorLabApp::dragTo(glm::vec2 pixel) {
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

Line EditorLabApp::rayThrough(glm::vec2 pixel) const {
    const glm::mat4 inverse = glm::inverse(m_viewProjection);
    const glm::vec2 ndc((pixel.x + 0.5f) / m_size.x * 2.0f - 1.0f, 1.0f - (pixel.y + 0.5f) / m_size.y * 2.0f);
    const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 b = glm::vec3(farPoint) / farPoint.w;
    return {a, b - a};
}

float EditorLabApp::gizmoLength(const EditorObject& object) const {
    return 0.6f + 0.5f * std::max(object.scale.x, std::max(object.scale.y, object.scale.z)) * (object.mesh == "shape:plane" ? 0.0f : 1.0f);
}

glm::vec2 EditorLabApp::toPixel(const glm::vec3& world) const {
    const glm::vec4 clip = m_viewProjection * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * m_size.x, (1.0f - ndc.y) * 0.5f * m_size.y};
}

int EditorLabApp::gizmoAxisNear(glm::vec2 pixel) const {
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

} // namespace stoa
