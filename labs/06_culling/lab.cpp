// Lab 06 app: a field of some four hundred columns and statues around the
// temple, 200 m across, under a sky. Every frame it asks the student's code
// (student/lab06.hpp) which objects the camera can see (bounds.cpp, frustum.cpp),
// which level of detail each needs (level_of_detail.cpp), and draws the sky
// with the student's skybox.glsl. The levels themselves are the framework's
// (stoa/geometry/LevelOfDetail.hpp: meshoptimizer's simplifier).
//
// Culling cannot be seen from the camera that culls, so a case can also show the
// field from high above (view = overview): the main camera's frustum in lines,
// every object coloured by the verdict: grey culled, blue too small to draw, and
// by level when drawn: green 0 (full detail), yellow 1, orange 2, red 3.
//
// Case keys besides the camera's (CameraRig.hpp):
//   view = camera | overview          what the picture shows (default camera)
//   cull = both | sphere | box | off  the tests that can drop an object (default both:
//                                     the sphere, then the box of those it keeps)
//   lod = on | off                    levels of detail (off: every object at full detail)
//   lod_pixels = hidden full          LodSettings: projected radii in pixels (default 2 80)
//   lod_colors = on | off             tint the camera view by level, as the overview (default off)
//   spheres = on | off                draw the world bounding spheres as lines (default off; always in the overview)
//   sky = on | off                    the skybox (default on)
//   overview = x y z  tx ty tz        the overview's eye and target (default 0 250 110  0 0 5)

#include "checks.hpp"
#include "lab06.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/DebugLines.hpp>
#include <stoa/geometry/LevelOfDetail.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/CubeMap.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/DebugLineRenderer.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/ObjectUniforms.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

enum class CullMode { Both, Sphere, Box, Off };

// The colours of the overview (and of lod_colors): by level, then the two verdicts.
const glm::vec3 kLevelColors[4] = {{0.15f, 0.8f, 0.2f}, {0.95f, 0.85f, 0.1f}, {1.0f, 0.5f, 0.05f}, {0.9f, 0.1f, 0.1f}};
const glm::vec3 kCulledColor{0.35f, 0.35f, 0.37f};
const glm::vec3 kHiddenColor{0.15f, 0.25f, 0.75f};

// A mesh in its levels of detail, uploaded, with the student's object-space sphere.
struct FieldMesh {
    std::vector<std::unique_ptr<stoa::GpuMesh>> levels;  // 0: the full mesh
    stoa::Mesh full;                                     // for meshBoundingSphere()
    stoa::Material material;
    std::shared_ptr<const stoa::Texture2D> diffuseMap;
    stoa::BoundingSphere sphere;                         // the student's, object space
};

struct FieldObject {
    FieldObject(int meshIndex, const glm::mat4& placed) : mesh(meshIndex), model(placed) {}
    int mesh = 0;        // index into the lab's meshes
    glm::mat4 model{1.0f};
    // This frame's verdicts.
    stoa::BoundingSphere sphere;   // the student's world sphere
    bool visible = true;
    int level = 0;                 // -1: too small to draw
};

// Numbers from a seed that every standard library turns into the same field
// (std::uniform_real_distribution may differ between libraries).
class FieldRandom {
public:
    explicit FieldRandom(std::uint32_t seed) : m_state(seed) {}
    float uniform(float low, float high) {
        m_state = m_state * 1664525u + 1013904223u;   // Numerical Recipes' LCG
        return low + (high - low) * static_cast<float>(m_state >> 8) / 16777216.0f;
    }

private:
    std::uint32_t m_state;
};

glm::mat4 placement(const glm::vec3& position, float yawDegrees, const glm::vec3& scale) {
    glm::mat4 model = glm::translate(glm::mat4(1.0f), position);
    model = glm::rotate(model, glm::radians(yawDegrees), glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::scale(model, scale);
}

class CullingLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        m_fieldProgram = &resources.loadProgram("basic/lit.vert", "basic/lit.frag");
        m_skyProgram = &resources.loadProgram("culling/skybox.vert", "culling/skybox.frag");
        m_debug = std::make_unique<stoa::DebugLineRenderer>(resources.loadProgram("debug/lines.vert", "debug/lines.frag"));
        m_fieldProgram->bindUniformBlock(stoa::FrameUniforms::kBlockName, stoa::FrameUniforms::kBinding);
        m_skyProgram->bindUniformBlock(stoa::FrameUniforms::kBlockName, stoa::FrameUniforms::kBinding);
        m_frame = std::make_unique<stoa::FrameUniforms>();
        m_objectUniforms = std::make_unique<stoa::ObjectUniforms>(*m_fieldProgram);

        const std::filesystem::path acropolis = stoa::paths::assetsDir() / "acropolis";
        m_column = addMesh(acropolis / "column.obj", {1.0f, 0.3f, 0.1f, 0.03f});
        m_statue = addMesh(acropolis / "statue.obj", {1.0f, 0.2f, 0.05f, 0.0125f});
        m_floor = addMesh(acropolis / "floor.obj", {1.0f});
        m_temple = addMesh(acropolis / "temple.obj", {1.0f});
        buildField();

        m_sky = stoa::CubeMap::fromFolder(stoa::paths::assetsDir() / "sky");
        m_skyCube = std::make_unique<stoa::GpuMesh>(stoa::shapes::cube(2.0f));
        m_scene.ambient = glm::vec3(0.35f, 0.37f, 0.42f);
        m_scene.directionalLights = {stoa::acropolisSun()};
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        m_view = spec.getChoice("view", {"camera", "overview"}, std::string("camera")) == "overview";
        const std::string cull = spec.getChoice("cull", {"both", "sphere", "box", "off"}, std::string("both"));
        m_cull = cull == "sphere" ? CullMode::Sphere : cull == "box" ? CullMode::Box : cull == "off" ? CullMode::Off : CullMode::Both;
        m_lod = spec.getSwitch("lod", true);
        if (spec.has("lod_pixels")) {
            const std::vector<float> pixels = spec.getNumbers("lod_pixels", 2, "hidden below, full detail at (pixels)");
            if (!(pixels[0] >= 0.0f && pixels[1] > pixels[0]))
                spec.reject("lod_pixels", "lod_pixels needs 0 <= hidden < full");
            m_lodSettings = {pixels[0], pixels[1]};
        } else {
            m_lodSettings = {};
        }
        m_lodColors = spec.getSwitch("lod_colors", false);
        m_spheres = spec.getSwitch("spheres", false);
        m_showSky = spec.getSwitch("sky", true);
        if (spec.has("overview")) {
            const std::vector<float> overview = spec.getNumbers("overview", 6, "eye x y z, target x y z");
            m_overviewEye = {overview[0], overview[1], overview[2]};
            m_overviewTarget = {overview[3], overview[4], overview[5]};
        }
        // The object-space spheres: student code, once per mesh.
        m_missing = "meshBoundingSphere()";
        for (FieldMesh& mesh : m_meshes) mesh.sphere = stoa::meshBoundingSphere(mesh.full);
        m_missing.reset();
    }

    void render(glm::ivec2 size) override {
        if (m_missing) throw stoa::NotImplemented(*m_missing);
        const stoa::Camera& camera = m_cameras.active();
        const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
        const glm::mat4 viewProjection = camera.projectionMatrix(aspect) * camera.viewMatrix();
        decide(viewProjection, camera, size.y);

        stoa::FrameBlock block = stoa::FrameUniforms::blockFor(camera, aspect, m_scene);
        if (m_view) {
            block.view = glm::lookAt(m_overviewEye, m_overviewTarget, glm::vec3(0.0f, 1.0f, 0.0f));
            block.projection = glm::perspective(glm::radians(50.0f), aspect, 1.0f, 1000.0f);
            block.cameraPosition = m_overviewEye;
        }
        m_frame->update(block);
        m_frame->bind();

        stoa::PassDescription pass = stoa::passInto(size);
        pass.clear.color = pass.clear.depth = true;
        pass.clear.colorValue = glm::vec4(m_clearColor, 1.0f);
        pass.state.cull = stoa::CullMode::None;   // statues are open below, floor tiles one-sided
        stoa::beginPass(pass);
        drawField(m_view);
        if (m_showSky && !m_view) drawSky();

        stoa::DebugLines lines;
        if (m_view) lines.frustum(viewProjection, glm::vec3(1.0f));
        for (const FieldObject& object : m_objects) {
            if (object.mesh == m_floor) continue;   // a tile's sphere would cover its neighbours
            if (m_view)
                horizontalCircle(lines, object.sphere, colorOf(object));   // from above, one circle reads best
            else if (m_spheres)
                lines.sphere(object.sphere, colorOf(object), 24);
        }
        if (lines.lineCount() > 0) {
            stoa::RenderState state;
            state.depth.test = !m_view;   // the overview shows every line
            stoa::StateCache::current().apply(state);
            m_debug->draw(lines, block.projection * block.view);
        }
    }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "sphere_turned_about_x") return lab06::checkSphereTurnedAboutX();
        if (spec.check == "planes_bound_clip_space") return lab06::checkPlanesBoundClipSpace();
        if (spec.check == "levels_of_detail") return lab06::checkLevelsOfDetail();
        if (spec.check == "inside_at_the_boundary") return lab06::checkInsideAtTheBoundary();
        return Lab::runCheck(spec);
    }

    bool keyPressed(unsigned char key) override {
        const bool used = toggle(key);
        if (used) std::printf("  (the last frame drew %zu of the %zu objects)\n", m_drawn, m_objects.size());
        return used;
    }

    std::vector<std::string> keyHelp() const override {
        return {"o            switch view: camera / overview from above (frustum, verdict colours)",
                "x            culling on / off",
                "l            levels of detail on / off",
                "k            colour the camera view by level of detail",
                "b            show the bounding spheres"};
    }

private:
    bool toggle(unsigned char key) {
        if (key == 'o') {
            m_view = !m_view;
            std::printf("view: %s\n", m_view ? "overview (the camera's frustum from above)" : "camera");
            return true;
        }
        if (key == 'l') {
            m_lod = !m_lod;
            std::printf("levels of detail %s\n", m_lod ? "on" : "off");
            return true;
        }
        if (key == 'x') {
            m_cull = m_cull == CullMode::Off ? CullMode::Both : CullMode::Off;
            std::printf("culling %s\n", m_cull == CullMode::Off ? "off" : "on (sphere, then box)");
            return true;
        }
        if (key == 'b') {
            m_spheres = !m_spheres;
            std::printf("bounding spheres %s\n", m_spheres ? "shown" : "hidden");
            return true;
        }
        if (key == 'k') {
            m_lodColors = !m_lodColors;
            std::printf("level colours %s\n", m_lodColors ? "on" : "off");
            return true;
        }
        return false;
    }

    int addMesh(const std::filesystem::path& file, const std::vector<float>& ratios) {
        const stoa::Model model = stoa::loadObj(file);
        FieldMesh mesh;
        mesh.full = model.parts.front().mesh;
        mesh.material = model.parts.front().material;
        if (!mesh.material.diffuseMap.empty()) mesh.diffuseMap = stoa::TextureCache::shared().load(mesh.material.diffuseMap);
        for (const stoa::LodLevel& level : stoa::buildLevelsOfDetail(mesh.full, ratios, 0.2f))
            mesh.levels.push_back(std::make_unique<stoa::GpuMesh>(level.mesh));
        m_meshes.push_back(std::move(mesh));
        return static_cast<int>(m_meshes.size()) - 1;
    }

    // The field: an 8 x 8 floor of 30 m tiles, the temple in the middle, and a
    // jittered 20 x 20 grid of columns (stretched tall or squat: non-uniform
    // scales) and statues (up to three times life size), 10 m apart.
    void buildField() {
        for (int i = 0; i < 8; ++i)
            for (int j = 0; j < 8; ++j)
                m_objects.emplace_back(m_floor, placement({-105.0f + 30.0f * i, 0.0f, -105.0f + 30.0f * j}, 0.0f, glm::vec3(1.0f)));
        m_objects.emplace_back(m_temple, placement({0.0f, 0.0f, 0.0f}, 0.0f, glm::vec3(1.0f)));
        FieldRandom random(6);
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 20; ++j) {
                const glm::vec3 position(-95.0f + 10.0f * i + random.uniform(-3.0f, 3.0f), 0.0f,
                                         -95.0f + 10.0f * j + random.uniform(-3.0f, 3.0f));
                const float yaw = random.uniform(0.0f, 360.0f);
                const bool statue = random.uniform(0.0f, 1.0f) < 0.3f;
                const float size = random.uniform(0.0f, 1.0f);
                const float stretch = random.uniform(0.6f, 1.8f);
                if (std::abs(position.x) < 12.0f && std::abs(position.z) < 16.0f) continue;  // the temple's ground
                if (statue)
                    m_objects.emplace_back(m_statue, placement(position, yaw, glm::vec3(1.0f + 2.0f * size)));
                else
                    m_objects.emplace_back(m_column, placement(position, yaw, glm::vec3(0.8f + 0.5f * size) * glm::vec3(1.0f, stretch, 1.0f)));
            }
    }

    // Every object's verdicts for the camera, with the student's functions.
    void decide(const glm::mat4& viewProjection, const stoa::Camera& camera, int viewportHeight) {
        m_missing = "worldBoundingSphere()";
        for (FieldObject& object : m_objects)
            object.sphere = stoa::worldBoundingSphere(m_meshes[object.mesh].sphere, object.model);
        m_missing.reset();

        std::optional<stoa::Frustum> frustum;
        if (m_cull != CullMode::Off) {
            m_missing = "frustumPlanes()";
            frustum = stoa::frustumPlanes(viewProjection);
        }
        for (FieldObject& object : m_objects) {
            object.visible = true;
            if ((m_cull == CullMode::Both || m_cull == CullMode::Sphere) && object.visible) {
                m_missing = "sphereInFrustum()";
                object.visible = stoa::sphereInFrustum(*frustum, object.sphere);
            }
            if ((m_cull == CullMode::Both || m_cull == CullMode::Box) && object.visible) {
                m_missing = "boxInFrustum()";
                const stoa::Aabb box = stoa::transformed(m_meshes[object.mesh].levels.front()->bounds(), object.model).box;
                object.visible = stoa::boxInFrustum(*frustum, box);
            }
            object.level = 0;
            const int levelCount = static_cast<int>(m_meshes[object.mesh].levels.size());
            if (m_lod) {
                m_missing = "lodQuality()";
                const float quality = stoa::lodQuality(object.sphere, camera.eyePosition(), camera.fovYDegrees(),
                                                       viewportHeight, m_lodSettings);
                m_missing = "levelOfDetail()";
                object.level = stoa::levelOfDetail(quality, levelCount);
                if (object.level >= levelCount) object.level = levelCount - 1;   // a wrong answer still draws
            }
        }
        m_missing.reset();
    }

    // The sphere's equator (its circle in the plane y = centre.y), 24 segments.
    static void horizontalCircle(stoa::DebugLines& lines, const stoa::BoundingSphere& sphere, const glm::vec3& color) {
        constexpr int kSegments = 24;
        for (int i = 0; i < kSegments; ++i) {
            const float a = 2.0f * glm::pi<float>() * static_cast<float>(i) / kSegments;
            const float b = 2.0f * glm::pi<float>() * static_cast<float>(i + 1) / kSegments;
            lines.line(sphere.center + sphere.radius * glm::vec3(std::cos(a), 0.0f, std::sin(a)),
                       sphere.center + sphere.radius * glm::vec3(std::cos(b), 0.0f, std::sin(b)), color);
        }
    }

    glm::vec3 colorOf(const FieldObject& object) const {
        if (!object.visible) return kCulledColor;
        if (object.level < 0) return kHiddenColor;
        return kLevelColors[std::min(object.level, 3)];
    }

    void drawField(bool overview) {
        m_fieldProgram->use();
        m_drawn = 0;
        for (const FieldObject& object : m_objects) {
            const FieldMesh& mesh = m_meshes[object.mesh];
            const bool drawn = object.visible && object.level >= 0;
            if (!overview && !drawn) continue;
            const int level = drawn ? std::max(object.level, 0) : static_cast<int>(mesh.levels.size()) - 1;
            stoa::DrawItem item;
            item.mesh = mesh.levels[level].get();
            item.model = object.model;
            item.normalMatrix = glm::inverseTranspose(glm::mat3(object.model));
            item.material = &mesh.material;
            item.diffuseMap = overview ? nullptr : mesh.diffuseMap.get();
            m_objectUniforms->apply(item);
            const bool tinted = overview || m_lodColors;
            m_fieldProgram->set("uTint", colorOf(object));
            m_fieldProgram->set("uTintAmount", tinted ? (object.mesh == m_floor ? 0.5f : 0.85f) : 0.0f);
            item.mesh->draw();
            if (drawn) ++m_drawn;
        }
    }

    void drawSky() {
        stoa::RenderState state;
        state.depth.func = GL_LEQUAL;   // the sky lies at depth 1, where the clear left it
        state.depth.write = false;
        state.cull = stoa::CullMode::None;   // seen from inside
        stoa::StateCache::current().apply(state);
        m_skyProgram->use();
        m_sky.bind(0);
        m_skyProgram->set("uSky", 0);
        m_skyCube->draw();
    }

    stoa::CameraRig m_cameras;
    stoa::Scene m_scene;
    const stoa::Program* m_fieldProgram = nullptr;
    const stoa::Program* m_skyProgram = nullptr;
    std::unique_ptr<stoa::DebugLineRenderer> m_debug;
    std::unique_ptr<stoa::FrameUniforms> m_frame;
    std::unique_ptr<stoa::ObjectUniforms> m_objectUniforms;
    std::vector<FieldMesh> m_meshes;
    std::vector<FieldObject> m_objects;
    int m_column = 0, m_statue = 0, m_floor = 0, m_temple = 0;
    stoa::CubeMap m_sky;
    std::unique_ptr<stoa::GpuMesh> m_skyCube;
    glm::vec3 m_clearColor{0.05f, 0.06f, 0.08f};

    bool m_view = false;   // true: the overview
    CullMode m_cull = CullMode::Both;
    bool m_lod = true;
    stoa::LodSettings m_lodSettings;
    bool m_lodColors = false;
    bool m_spheres = false;
    bool m_showSky = true;
    glm::vec3 m_overviewEye{0.0f, 250.0f, 110.0f};
    glm::vec3 m_overviewTarget{0.0f, 0.0f, 5.0f};
    std::size_t m_drawn = 0;
    std::optional<std::string> m_missing;   // the student function that has not run yet
};

} // namespace

int main(int argc, char** argv) {
    CullingLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
