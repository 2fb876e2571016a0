// Lab 07 app: the Acropolis (stoa/scene/AcropolisScene.hpp), three ways.
//   view = shaded    lit by the sun; with `pick`, the object under that pixel
//                    (read back from the ID buffer) outlined with the student's
//                    outlineAt() (id_buffer.glsl)
//   view = ids       the ID buffer in false colour: each object's 32-bit id,
//                    packed and unpacked by the student's id_buffer.glsl
//   view = raycast   made on the CPU, one ray per pixel (rayThroughPixel()) through
//                    the student's BVH (buildBvh(), intersectBvh()), shaded by the
//                    normal of the nearest hit and darkened with its distance
//   view = ball      the shaded scene with a ball dropped into it, bouncing off the
//                    triangles the student's BVH finds (bounce.cpp), throwing sparks
//                    drawn as billboards (particles.glsl), after `time` seconds
//                    simulated in frames of the lengths `frame_ms` gives
// In the window a click (press and release without dragging) picks: the object's
// name, and the distance along the student's ray to what it hit, are printed.
//
// Case keys besides the camera's (CameraRig.hpp):
//   view = shaded | ids | raycast | ball   what the picture shows (default shaded)
//   pick = x y                        pick the pixel (x, y), from the top-left corner
//   outline_radius = r                the outline's half-width in pixels, 1..8 (default 2)
//   raycast_far = d                   distance at which the ray-cast picture's shading
//                                     has faded to 30% (default 60)
//   ball = x y z  vx vy vz            the ball's start and velocity (view = ball; default
//                                     -1.5 6 6  0 1 -3.5: above the columns, thrown towards the temple)
//   time = seconds                    how long to simulate, 0 to 10 (default 2)
//   frame_ms = t1 t2 ...              the frames' lengths in milliseconds, repeated in turn
//                                     (default 16.667: 60 frames a second)
// In the window, `b` throws the ball from the eye along the view.

#include "checks.hpp"
#include "lab07.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/gl/VertexArray.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/render/TextureOverlay.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/ObjectUniforms.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_precision.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

enum class View { Shaded, Ids, RayCast, Ball };

// One object of the scene: a name, an id, and its pieces (one per material).
struct PickableObject {
    std::string name;
    std::uint32_t id = 0;
};

struct DrawnPiece {
    const stoa::GpuMesh* mesh = nullptr;
    stoa::Material material;
    std::shared_ptr<const stoa::Texture2D> diffuseMap;
    glm::mat4 model{1.0f};
    int object = 0;
};

// Ids that differ in every byte, none 0 (the background): an integer hash of
// the object's index (the "lowbias32" mixer), so that a bug that keeps fewer
// than 32 bits shows.
std::uint32_t idOf(int index) {
    std::uint32_t x = static_cast<std::uint32_t>(index) + 1u;
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x == 0u ? 1u : x;
}

// The framework's reading of a texel of the ID buffer: bytes least significant
// first, as the docs define packObjectId().
std::uint32_t idFromBytes(const std::array<std::uint8_t, 4>& bytes) {
    return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8u) |
           (static_cast<std::uint32_t>(bytes[2]) << 16u) | (static_cast<std::uint32_t>(bytes[3]) << 24u);
}

class PickingLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        m_litProgram = &resources.loadProgram("basic/lit.vert", "basic/lit.frag");
        m_idProgram = &resources.loadProgram("picking/ids.vert", "picking/ids.frag");
        m_idViewProgram = &resources.loadProgram("basic/image.vert", "picking/id_view.frag");
        m_outlineProgram = &resources.loadProgram("basic/image.vert", "picking/outline.frag");
        m_imageProgram = &resources.loadProgram("basic/image.vert", "basic/image.frag");
        m_sparkProgram = &resources.loadProgram("picking/sparks.vert", "picking/sparks.frag");
        for (const stoa::Program* program : {m_litProgram, m_idProgram, m_sparkProgram})
            program->bindUniformBlock(stoa::FrameUniforms::kBlockName, stoa::FrameUniforms::kBinding);
        m_frame = std::make_unique<stoa::FrameUniforms>();
        m_litUniforms = std::make_unique<stoa::ObjectUniforms>(*m_litProgram);
        m_overlay = std::make_unique<stoa::TextureOverlay>();
        m_ballMesh = std::make_unique<stoa::GpuMesh>(stoa::shapes::sphere(1.0f, 32, 16));
        m_ballMaterial.diffuse = glm::vec3(0.75f, 0.45f, 0.2f);   // bronze
        m_ballMaterial.ambient = m_ballMaterial.diffuse;
        m_sparkBuffer = std::make_unique<stoa::Buffer>(GL_ARRAY_BUFFER);
        m_sparkArray = std::make_unique<stoa::VertexArray>();
        m_sparkArray->attribute(0, *m_sparkBuffer, 4, GL_FLOAT, 4 * sizeof(float), 0);
        m_sparkArray->divisor(0, 1);

        std::map<const stoa::Mesh*, std::shared_ptr<stoa::GpuMesh>> uploaded;
        std::map<std::string, int> objectByName;
        for (const stoa::AcropolisPiece& piece : stoa::acropolisPieces()) {
            auto found = objectByName.find(piece.name);
            if (found == objectByName.end()) {
                const int index = static_cast<int>(m_objects.size());
                m_objects.push_back({piece.name, idOf(index)});
                found = objectByName.emplace(piece.name, index).first;
            }
            std::shared_ptr<stoa::GpuMesh>& mesh = uploaded[piece.mesh];
            if (!mesh) mesh = std::make_shared<stoa::GpuMesh>(*piece.mesh);
            m_meshes.push_back(mesh);
            DrawnPiece drawn{mesh.get(), piece.material, nullptr, piece.model, found->second};
            if (!piece.material.diffuseMap.empty()) drawn.diffuseMap = stoa::TextureCache::shared().load(piece.material.diffuseMap);
            m_pieces.push_back(std::move(drawn));
            // The piece's triangles in world space, for the BVH.
            const stoa::Mesh& mesh3d = *piece.mesh;
            for (std::size_t t = 0; t + 2 < mesh3d.indices.size(); t += 3) {
                stoa::Triangle triangle;
                triangle.p0 = glm::vec3(piece.model * glm::vec4(mesh3d.vertices[mesh3d.indices[t]].position, 1.0f));
                triangle.p1 = glm::vec3(piece.model * glm::vec4(mesh3d.vertices[mesh3d.indices[t + 1]].position, 1.0f));
                triangle.p2 = glm::vec3(piece.model * glm::vec4(mesh3d.vertices[mesh3d.indices[t + 2]].position, 1.0f));
                triangle.object = found->second;
                m_triangles.push_back(triangle);
            }
        }
        m_scene.ambient = glm::vec3(0.3f, 0.32f, 0.36f);
        m_scene.directionalLights = {stoa::acropolisSun()};
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        const std::string view = spec.getChoice("view", {"shaded", "ids", "raycast", "ball"}, std::string("shaded"));
        m_view = view == "ids" ? View::Ids : view == "raycast" ? View::RayCast : view == "ball" ? View::Ball : View::Shaded;
        const std::vector<float> ball = spec.has("ball") ? spec.getNumbers("ball", 6, "position x y z, velocity x y z")
                                                         : std::vector<float>{-1.5f, 6.0f, 6.0f, 0.0f, 1.0f, -3.5f};
        m_ballStart = stoa::Ball{{ball[0], ball[1], ball[2]}, {ball[3], ball[4], ball[5]}, 0.3f};
        m_time = static_cast<float>(spec.getNumber("time", 2.0));
        if (!(m_time >= 0.0f && m_time <= 10.0f)) spec.reject("time", "time must be from 0 to 10 seconds");
        m_frameSeconds = {1.0f / 60.0f};
        if (spec.has("frame_ms")) {
            m_frameSeconds.clear();
            for (const std::string& word : splitWords(spec.getString("frame_ms"))) {
                char* end = nullptr;
                const float milliseconds = std::strtof(word.c_str(), &end);
                if (end == word.c_str() || *end != '\0' || !(milliseconds > 0.0f && milliseconds <= 1000.0f))
                    spec.reject("frame_ms", "frame_ms needs frame lengths in milliseconds, each in (0, 1000], got '" + word + "'");
                m_frameSeconds.push_back(milliseconds / 1000.0f);
            }
            if (m_frameSeconds.empty()) spec.reject("frame_ms", "frame_ms needs at least one frame length");
        }
        m_simulated = false;
        m_pick.reset();
        if (spec.has("pick")) {
            const std::vector<float> pixel = spec.getNumbers("pick", 2, "pixel x y from the top-left corner");
            if (pixel[0] < 0.0f || pixel[1] < 0.0f || pixel[0] >= static_cast<float>(spec.width) ||
                pixel[1] >= static_cast<float>(spec.height))
                spec.reject("pick", "pick needs a pixel inside the picture: 0 <= x < width, 0 <= y < height");
            m_pick = glm::vec2(pixel[0], pixel[1]);
            m_pickFrame = glm::vec2(spec.width, spec.height);   // in the case's picture; the window may be larger
        }
        m_outlineRadius = spec.getIntInRange("outline_radius", 1, 8, 2);
        m_rayCastFar = static_cast<float>(spec.getNumber("raycast_far", 60.0));
        if (!(m_rayCastFar > 0.0f)) spec.reject("raycast_far", "raycast_far must be greater than 0");
        m_selected = 0;
    }

    void render(glm::ivec2 size) override {
        m_size = size;
        const stoa::Camera& camera = m_cameras.active();
        const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
        m_frame->update(camera, aspect, m_scene);
        m_frame->bind();

        if (m_view == View::RayCast) {
            drawRayCast(size, camera);
            return;
        }
        if (m_view == View::Ball) {
            if (!m_simulated) simulateCase();
            drawShaded(size);
            drawBallAndSparks();
            return;
        }
        drawIds(size);
        if (m_pick) {
            const glm::vec2 pixel = *m_pick * glm::vec2(size) / (m_pickFrame ? *m_pickFrame : glm::vec2(size));
            m_selected = idAtPixel(glm::clamp(glm::ivec2(pixel), glm::ivec2(0), size - 1));
            m_pickFrame.reset();
            m_pick.reset();
        }
        if (m_view == View::Ids) {
            m_idTarget->bindColorTexture(0);
            m_idViewProgram->use();
            m_idViewProgram->set("uIds", 0);
            m_overlay->draw(*m_idViewProgram, {0, 0, size.x, size.y});
            return;
        }
        drawShaded(size);
        if (m_selected != 0) {
            m_idTarget->bindColorTexture(0);
            m_outlineProgram->use();
            m_outlineProgram->set("uIds", 0);
            m_outlineProgram->set("uSelected", m_selected);
            m_outlineProgram->set("uRadius", m_outlineRadius);
            m_outlineProgram->set("uOutlineColor", glm::vec3(1.0f, 0.55f, 0.05f));
            m_overlay->draw(*m_outlineProgram, {0, 0, size.x, size.y});
        }
    }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "slab_test_table") return lab07::checkSlabTestTable();
        if (spec.check == "bvh_cheapest_split") return lab07::checkBvhCheapestSplit();
        if (spec.check == "bvh_structure") return lab07::checkBvhStructure();
        if (spec.check == "closest_point_on_triangle") return lab07::checkClosestPointOnTriangle();
        if (spec.check == "deep_tree_walks") return lab07::checkDeepTreeWalks();
        if (spec.check == "fixed_step_bookkeeping") return lab07::checkFixedStepBookkeeping();
        if (spec.check == "triangle_hits_on_the_edges") return lab07::checkTriangleHitsOnTheEdges();
        if (spec.check == "ray_starts_on_the_near_plane") return lab07::checkRayStartsOnTheNearPlane();
        return Lab::runCheck(spec);
    }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    bool handleEvent(const stoa::InputEvent& event) override {
        // A click: pressed and released within a few pixels (a drag turns the camera).
        if (event.type == stoa::InputEvent::Type::MouseDown && event.button == stoa::MouseButton::Left)
            m_pressedAt = event.position;
        if (event.type == stoa::InputEvent::Type::MouseUp && event.button == stoa::MouseButton::Left && m_pressedAt &&
            glm::length(event.position - *m_pressedAt) < 3.0f) {
            m_pick = event.position;
            m_pickFrame.reset();   // window pixels
            reportPick(event.position);
        }
        if (event.type == stoa::InputEvent::Type::MouseUp) m_pressedAt.reset();
        return false;
    }

    bool keyPressed(unsigned char key) override {
        if (key == 'v') {
            m_view = m_view == View::Shaded ? View::Ids : m_view == View::Ids ? View::RayCast : View::Shaded;
            std::printf("view: %s\n", m_view == View::Shaded ? "shaded" : m_view == View::Ids ? "ID buffer" : "ray cast (your BVH, on the CPU)");
            return true;
        }
        if (key == 'b') {
            // Thrown from the eye along the view, 12 m/s, as the window runs (update()).
            const stoa::Camera& camera = m_cameras.active();
            const glm::vec3 forward = glm::normalize(camera.lookTarget() - camera.eyePosition());
            m_simulation = stoa::Simulation{};
            m_simulation.ball = {camera.eyePosition() + forward, forward * 12.0f, 0.3f};
            m_view = View::Ball;
            m_simulated = true;
            m_live = true;
            std::printf("ball thrown\n");
            return true;
        }
        return false;
    }

    void update(float seconds) override {
        if (m_view != View::Ball || !m_live) return;
        const int before = m_simulation.contacts;
        stoa::advanceSimulation(m_simulation, bvh(), seconds);
        if (m_simulation.contacts > before) std::printf("contact at %.2f s: %zu sparks alive\n", m_simulation.time, m_simulation.particles.size());
    }

    std::vector<std::string> keyHelp() const override {
        return {"click        pick the object under the mouse (outlined; name and distance printed)",
                "v            switch view: shaded / ID buffer / ray cast with your BVH",
                "b            throw the ball from the eye along the view (it bounces, sparks fly)"};
    }

private:
    // The student's BVH, built at the first ray; the build's stubs throw from here.
    const stoa::Bvh& bvh() {
        if (!m_bvh) m_bvh = stoa::buildBvh(m_triangles);
        return *m_bvh;
    }

    void reportPick(const glm::vec2& pixel) {
        const stoa::Camera& camera = m_cameras.active();
        const float aspect = static_cast<float>(m_size.x) / static_cast<float>(m_size.y);
        const glm::mat4 inverse = glm::inverse(camera.projectionMatrix(aspect) * camera.viewMatrix());
        const stoa::Ray ray = stoa::rayThroughPixel(pixel + 0.5f, m_size, inverse);
        const stoa::Hit hit = stoa::intersectBvh(bvh(), ray);
        if (!hit.found()) {
            std::printf("picked nothing at %d, %d\n", int(pixel.x), int(pixel.y));
            return;
        }
        std::printf("picked '%s' at %.2f m (pixel %d, %d)\n", m_objects[bvh().triangles[hit.triangle].object].name.c_str(),
                    hit.t, int(pixel.x), int(pixel.y));
    }

    void drawIds(glm::ivec2 size) {
        if (!m_idTarget || m_idTarget->width() != size.x || m_idTarget->height() != size.y) {
            stoa::FramebufferOptions options;
            options.colorFormats = {GL_RGBA8UI};
            m_idTarget = std::make_unique<stoa::Framebuffer>(size.x, size.y, options);
        }
        const GLuint previous = stoa::StateCache::current().drawFramebuffer();
        stoa::PassDescription pass = stoa::passInto(*m_idTarget);
        pass.clear.depth = true;
        pass.state.cull = stoa::CullMode::None;
        stoa::beginPass(pass);
        const GLuint zero[4] = {0, 0, 0, 0};
        glClearBufferuiv(GL_COLOR, 0, zero);   // id 0: the background (an integer target clears with its own call)
        m_idProgram->use();
        for (const DrawnPiece& piece : m_pieces) {
            m_idProgram->set("uModel", piece.model);
            m_idProgram->set("uObjectId", m_objects[piece.object].id);
            piece.mesh->draw();
        }
        stoa::StateCache::current().bindFramebuffer(previous);
    }

    std::uint32_t idAtPixel(glm::ivec2 pixel) const {
        std::array<std::uint8_t, 4> bytes{};
        m_idTarget->readPixels(0, pixel.x, m_idTarget->height() - 1 - pixel.y, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE,
                               bytes.data());
        const std::uint32_t id = idFromBytes(bytes);
        for (const PickableObject& object : m_objects)
            if (object.id == id) {
                std::printf("picked '%s' (id %08x)\n", object.name.c_str(), id);
                return id;
            }
        std::printf("picked no object (id %08x)\n", id);
        return id;
    }

    void drawShaded(glm::ivec2 size) {
        stoa::PassDescription pass = stoa::passInto(size);
        pass.clear.color = pass.clear.depth = true;
        pass.clear.colorValue = glm::vec4(0.55f, 0.68f, 0.85f, 1.0f);
        pass.state.cull = stoa::CullMode::None;
        stoa::beginPass(pass);
        m_litProgram->use();
        m_litProgram->set("uTintAmount", 0.0f);
        for (const DrawnPiece& piece : m_pieces) {
            stoa::DrawItem item;
            item.mesh = piece.mesh;
            item.model = piece.model;
            item.normalMatrix = glm::inverseTranspose(glm::mat3(piece.model));
            item.material = &piece.material;
            item.diffuseMap = piece.diffuseMap.get();
            m_litUniforms->apply(item);
            piece.mesh->draw();
        }
    }

    // The case's simulation, from the start, in frames of the case's lengths.
    void simulateCase() {
        m_simulation = stoa::Simulation{};
        m_simulation.ball = m_ballStart;
        double elapsed = 0.0;
        for (std::size_t frame = 0; elapsed < m_time; ++frame) {
            const float seconds = std::min(m_frameSeconds[frame % m_frameSeconds.size()], static_cast<float>(m_time - elapsed));
            stoa::advanceSimulation(m_simulation, bvh(), seconds);
            elapsed += seconds;
        }
        m_simulated = true;
        m_live = false;
        std::printf("simulated %.3f s in %d steps: %d contacts, %zu sparks alive\n", m_simulation.time,
                    static_cast<int>(std::lround(m_simulation.time / m_simulation.settings.step)), m_simulation.contacts,
                    m_simulation.particles.size());
    }

    void drawBallAndSparks() {
        // The ball, lit like the scene (the pass drawShaded() began is still on).
        stoa::DrawItem item;
        item.mesh = m_ballMesh.get();
        item.model = glm::scale(glm::translate(glm::mat4(1.0f), m_simulation.ball.position), glm::vec3(m_simulation.ball.radius));
        item.normalMatrix = glm::mat3(1.0f);
        item.material = &m_ballMaterial;
        m_litProgram->use();
        m_litUniforms->apply(item);
        m_ballMesh->draw();
        if (m_simulation.particles.empty()) return;

        // The sparks: additive, depth-tested against the scene but not written.
        std::vector<float> sparks;
        sparks.reserve(4 * m_simulation.particles.size());
        for (const stoa::Particle& spark : m_simulation.particles)
            sparks.insert(sparks.end(), {spark.position.x, spark.position.y, spark.position.z, spark.age / spark.lifetime});
        m_sparkBuffer->upload(sparks, GL_STREAM_DRAW);
        stoa::RenderState state;
        state.depth.write = false;
        state.cull = stoa::CullMode::None;
        state.blend = stoa::BlendMode::Additive;
        stoa::StateCache::current().apply(state);
        m_sparkProgram->use();
        m_sparkProgram->set("uHalfSize", 0.07f);
        m_sparkArray->bind();
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(m_simulation.particles.size()));
    }

    static std::vector<std::string> splitWords(const std::string& text) {
        std::vector<std::string> words;
        std::string word;
        for (char c : text + " ") {
            if (c == ' ' || c == '\t') {
                if (!word.empty()) words.push_back(word);
                word.clear();
            } else {
                word += c;
            }
        }
        return words;
    }

    void drawRayCast(glm::ivec2 size, const stoa::Camera& camera) {
        const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
        const glm::mat4 inverse = glm::inverse(camera.projectionMatrix(aspect) * camera.viewMatrix());
        const stoa::Bvh& tree = bvh();
        stoa::Image image(size.x, size.y, 4);
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const stoa::Ray ray = stoa::rayThroughPixel(glm::vec2(x, y) + 0.5f, size, inverse);
                const stoa::Hit hit = stoa::intersectBvh(tree, ray);
                glm::vec3 color(0.05f, 0.06f, 0.08f);
                if (hit.found()) {
                    const stoa::Triangle& triangle = tree.triangles[hit.triangle];
                    glm::vec3 normal = glm::normalize(glm::cross(triangle.p1 - triangle.p0, triangle.p2 - triangle.p0));
                    if (glm::dot(normal, ray.direction) > 0.0f) normal = -normal;   // the side facing the eye
                    const float fade = 1.0f - 0.7f * std::min(hit.t / m_rayCastFar, 1.0f);
                    color = (normal * 0.5f + 0.5f) * fade;
                }
                image.setPixel(x, y, glm::u8vec4(glm::clamp(color, 0.0f, 1.0f) * 255.0f + 0.5f, 255));
            }
        stoa::TextureOptions options;
        options.mipmaps = false;
        options.linear = false;
        options.wrap = GL_CLAMP_TO_EDGE;
        m_rayCastTexture = std::make_unique<stoa::Texture2D>(stoa::Texture2D::fromImage(image, options));
        stoa::PassDescription pass = stoa::passInto(size);
        pass.clear.color = pass.clear.depth = true;
        stoa::beginPass(pass);
        m_rayCastTexture->bind(0);
        m_imageProgram->use();
        m_imageProgram->set("uImage", 0);
        m_overlay->draw(*m_imageProgram, {0, 0, size.x, size.y});
    }

    stoa::CameraRig m_cameras;
    stoa::Scene m_scene;
    const stoa::Program* m_litProgram = nullptr;
    const stoa::Program* m_idProgram = nullptr;
    const stoa::Program* m_idViewProgram = nullptr;
    const stoa::Program* m_outlineProgram = nullptr;
    const stoa::Program* m_imageProgram = nullptr;
    const stoa::Program* m_sparkProgram = nullptr;
    std::unique_ptr<stoa::FrameUniforms> m_frame;
    std::unique_ptr<stoa::ObjectUniforms> m_litUniforms;
    std::unique_ptr<stoa::TextureOverlay> m_overlay;
    std::unique_ptr<stoa::Framebuffer> m_idTarget;
    std::unique_ptr<stoa::Texture2D> m_rayCastTexture;
    std::vector<std::shared_ptr<stoa::GpuMesh>> m_meshes;
    std::vector<DrawnPiece> m_pieces;
    std::vector<PickableObject> m_objects;
    std::vector<stoa::Triangle> m_triangles;
    std::optional<stoa::Bvh> m_bvh;
    std::unique_ptr<stoa::GpuMesh> m_ballMesh;
    stoa::Material m_ballMaterial;
    std::unique_ptr<stoa::Buffer> m_sparkBuffer;
    std::unique_ptr<stoa::VertexArray> m_sparkArray;
    stoa::Simulation m_simulation;
    stoa::Ball m_ballStart;
    float m_time = 2.0f;
    std::vector<float> m_frameSeconds{1.0f / 60.0f};
    bool m_simulated = false;   // m_simulation holds the case's state (or the window's throw)
    bool m_live = false;        // the window advances it

    View m_view = View::Shaded;
    std::optional<glm::vec2> m_pick;
    std::optional<glm::vec2> m_pickFrame;   // the picture size m_pick is given in; none: the frame's
    std::optional<glm::vec2> m_pressedAt;
    std::uint32_t m_selected = 0;
    int m_outlineRadius = 2;
    float m_rayCastFar = 60.0f;
    glm::ivec2 m_size{1, 1};
};

} // namespace

int main(int argc, char** argv) {
    PickingLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
