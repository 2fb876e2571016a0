// Lab 11's app: drawing a frame: the pick pass, the shaded and deferred
// views, the selection's outline and gizmo, the stencil view.

#include "editor_app.hpp"

namespace stoa {

void EditorLabApp::updateFrame(const Camera& camera) {
    Scene lights;
    lights.ambient = m_scene.ambient;
    lights.directionalLights = {DirectionalLight{m_scene.sunDirection, m_scene.sunColor}};
    lights.pointLights = pointLights();
    m_aspect = static_cast<float>(m_size.x) / static_cast<float>(m_size.y);
    m_frame->update(camera, m_aspect, lights);
    m_frame->bind();
    m_viewProjection = camera.projectionMatrix(m_aspect) * camera.viewMatrix();
}

glm::mat4 EditorLabApp::modelOf(const EditorObject& object) const {
    return modelMatrix(object.position, object.rotationDegrees, object.scale);
}

void EditorLabApp::drawMeshes(const EditorObject& object) {
    for (const GpuMesh* mesh : m_assets->meshes(object.mesh)) mesh->draw();
}

StencilReadback EditorLabApp::drawPickPass() {
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

void EditorLabApp::drawShaded() {
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

Material EditorLabApp::materialOf(const EditorMaterial* found) {
    Material material;
    if (found) {
        material.ambient = material.diffuse = found->diffuse;
        material.specular = found->specular;
        material.shininess = found->shininess;
    }
    return material;
}

DrawItem EditorLabApp::drawItemOf(const EditorObject& object, const EditorMaterial* found, const Material& material) {
    DrawItem item;
    item.model = modelOf(object);
    item.normalMatrix = glm::inverseTranspose(glm::mat3(item.model));
    item.material = &material;
    if (found && !found->diffuseMap.empty())
        item.diffuseMap = m_sceneFile.empty() && found->diffuseMap == "panel" ? &panelTexture() : m_assets->texture(found->diffuseMap);
    return item;
}

std::vector<PointLight> EditorLabApp::pointLights() const {
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

void EditorLabApp::drawDeferred() {
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

const Texture2D* EditorLabApp::normalMap(const std::string& name) {
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

void EditorLabApp::drawSelection() {
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

void EditorLabApp::drawStencilView() {
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

} // namespace stoa
