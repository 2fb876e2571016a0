// Lab 05 app: shadow maps. The student's depth pass (shadow_pass.cpp) and
// light-space matrices (light_space.cpp) make the map; shaders/shadows/shadowed.frag
// lights the scene with the student's lab-02 lighting and tests it against the
// map with the student's shadows.glsl. The framework's ShadowRenderer
// (stoa/render/ShadowRenderer.hpp) puts the passes together, calling the
// student's functions through the framework's student-code table (hand_over.cpp).
// With cascades (cascades = N), the student's cascades.cpp fits one map per slice
// of the camera's frustum and shaders/shadows/cascaded.frag picks the slice with
// the student's cascades.glsl.
//
// Case keys besides the camera's (CameraRig.hpp):
//   scene = acropolis | large | shapes    the Acropolis (default); the Acropolis with a long
//                                         colonnade and floor down to z = -105 (for cascades);
//                                         or lab 01's shapes on a floor
//   ambient = r g b                       scene ambient light
//   light = sun | point                   which light casts the shadows (default sun)
//   sun = dx dy dz  r g b                 the directional light (light = sun)
//   point = x y z  r g b                  the point light (light = point)
//   point_target = x y z                  where its perspective map looks (default: the scene's centre)
//   point_fov = degrees                   its map's field of view (default 90)
//   point_range = near far                its map's depth range, world units (default 0.5 30)
//   attenuation = kc kl kq                the point light's falloff (default 1 0.045 0.0075)
//   pcf = single | 2x2 | 3x3              the filter (default single)
//   bias = slope min max                  shadows.glsl's bias, window-depth units (default:
//                                         kSunBias or kPointBias times 1024 / shadow_map_size)
//   shadow_map_size = texels              the map's side (default 1024)
//   shadows = on | off                    (default on)
//   show_map = on | off                   the map (the cascades' maps) in a corner (default off)
//   cascades = 0..4                       cascaded shadow maps for the sun, 0: one map (default; key n: 4)
//   cascade_lambda = 0..1                 the practical split's blend (default 0.75)
//   cascade_far = d                       view depth the last cascade ends at (default 80)
//   cascade_colors = on | off             tint each cascade (default off)
// Cascades use their own bias, a few texels of each map (ShadowRenderer.cpp); `bias` is
// for the single map.

#include "checks.hpp"

#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include "lab05.hpp"
#include <stoa/render/ShadowRenderer.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/ShapesScene.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

// Default biases (slope, min, max) in window depth. An orthographic map's depth
// is linear over the fitted box (some 15-40 world units here); a perspective
// map's depth crowds towards 1 beyond the near plane, so the same world offset
// is a much smaller depth step there.
constexpr glm::vec3 kSunBias{0.004f, 0.001f, 0.015f};
constexpr glm::vec3 kPointBias{0.0008f, 0.0004f, 0.004f};

struct SceneBounds {
    glm::vec3 min;
    glm::vec3 max;
};

// The large scene: the Acropolis, three more floor tiles behind it (the floor is
// 30 m square) and two rows of columns 4 m apart along -Z, to the right of the
// temple, from z = 12 to z = -100: a colonnade too long for one shadow map.
constexpr float kColonnadeRowsX[2] = {9.0f, 13.0f};
constexpr float kColonnadeStart = 12.0f;
constexpr float kColonnadeStep = 4.0f;
constexpr int kColonnadeLength = 29;   // columns per row
constexpr int kExtraFloorTiles = 3;
constexpr float kFloorTile = 30.0f;

// Adds `fileName`'s parts at each of `positions`, sharing one upload per part.
void placeCopies(stoa::Scene& scene, const std::string& fileName, const std::string& name,
                 const std::vector<glm::vec3>& positions) {
    const stoa::Model& model = stoa::acropolisModel(fileName);
    for (const stoa::ModelPart& part : model.parts) {
        auto mesh = std::make_shared<const stoa::GpuMesh>(part.mesh);
        for (std::size_t i = 0; i < positions.size(); ++i) {
            auto& object = scene.add(std::make_unique<stoa::MeshObject>(mesh, part.material));
            object.name = name + " " + std::to_string(i + 1);
            object.position = positions[i];
        }
    }
}

SceneBounds buildLargeScene(stoa::Scene& scene) {
    stoa::buildAcropolisScene(scene);
    std::vector<glm::vec3> tiles;
    for (int i = 1; i <= kExtraFloorTiles; ++i) tiles.emplace_back(0.0f, 0.0f, -kFloorTile * static_cast<float>(i));
    placeCopies(scene, "floor.obj", "floor tile", tiles);
    std::vector<glm::vec3> columns;
    for (float x : kColonnadeRowsX)
        for (int i = 0; i < kColonnadeLength; ++i)
            columns.emplace_back(x, 0.0f, kColonnadeStart - kColonnadeStep * static_cast<float>(i));
    placeCopies(scene, "column.obj", "colonnade column", columns);

    // The Acropolis's bounds, stretched over the extra tiles.
    auto [low, high] = stoa::acropolisBounds();
    low.z -= kFloorTile * static_cast<float>(kExtraFloorTiles);
    return {low, high};
}

class ShadowsLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        const stoa::Program& depth = resources.loadProgram("shadows/depth.vert", "shadows/depth.frag");
        const stoa::Program& shadowed = resources.loadProgram("shadows/shadowed.vert", "shadows/shadowed.frag");
        const stoa::Program& mapView = resources.loadProgram("shadows/depth_view.vert", "shadows/depth_view.frag");
        m_renderer = std::make_unique<stoa::ShadowRenderer>(depth, shadowed, mapView);
        m_depthProgram = &depth;
        m_resources = &resources;
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        const std::string sceneName = spec.getChoice("scene", {"acropolis", "large", "shapes"}, std::string("acropolis"));
        if (sceneName == "acropolis") {
            stoa::buildAcropolisScene(m_scene);
            const auto [low, high] = stoa::acropolisBounds();
            m_bounds = {low, high};
            m_scene.directionalLights.clear();   // the case picks the light
        } else if (sceneName == "large") {
            m_bounds = buildLargeScene(m_scene);
            m_scene.directionalLights.clear();
        } else {
            stoa::buildShapesScene(m_scene);
            m_bounds = {{-5.0f, 0.0f, -5.0f}, {5.0f, 2.5f, 5.0f}};
        }
        m_cameras.loadCase(spec);
        m_scene.ambient = spec.getVec3("ambient", glm::vec3(0.12f, 0.13f, 0.15f));

        m_settings = {};
        m_settings.enabled = spec.getSwitch("shadows", true);
        m_settings.showMap = spec.getSwitch("show_map", false);
        m_settings.mapSize = spec.getIntInRange("shadow_map_size", 16, 8192, 1024);
        const std::string pcf = spec.getChoice("pcf", {"single", "2x2", "3x3"}, std::string("single"));
        m_settings.pcf = pcf == "3x3"   ? stoa::PcfMode::ThreeByThree
                         : pcf == "2x2" ? stoa::PcfMode::TwoByTwo
                                        : stoa::PcfMode::Single;

        m_settings.cascades.count = spec.getIntInRange("cascades", 0, stoa::ShadowRenderer::kMaxCascades, 0);
        m_settings.cascades.lambda = static_cast<float>(spec.getNumberInRange("cascade_lambda", 0.0, 1.0, 0.75));
        m_settings.cascades.far = static_cast<float>(spec.getNumber("cascade_far", 80.0));
        if (!(m_settings.cascades.far > 0.0f)) spec.reject("cascade_far", "cascade_far must be greater than 0");
        m_settings.cascades.colors = spec.getSwitch("cascade_colors", false);
        m_cascadeCountOn = m_settings.cascades.count > 0 ? m_settings.cascades.count : 4;

        // The default biases suit a 1024^2 map; a coarser map's texels span more
        // depth and need proportionally more.
        const float mapScale = 1024.0f / static_cast<float>(m_settings.mapSize);
        m_light = {};
        const std::string light = spec.getChoice("light", {"sun", "point"}, std::string("sun"));
        if (light == "sun") {
            const std::vector<float> sun = spec.getNumbers("sun", 6, "direction x y z, colour r g b");
            const glm::vec3 direction(sun[0], sun[1], sun[2]);
            m_scene.directionalLights.push_back({direction, {sun[3], sun[4], sun[5]}});
            m_settings.bias = spec.getVec3("bias", kSunBias * mapScale);
            m_light.perspective = false;
            m_light.lightSpaceMatrix = stoa::directionalLightMatrix(direction, m_bounds.min, m_bounds.max);
        } else if (light == "point") {
            const std::vector<float> point = spec.getNumbers("point", 6, "position x y z, colour r g b");
            const glm::vec3 position(point[0], point[1], point[2]);
            const glm::vec3 attenuation = spec.getVec3("attenuation", glm::vec3(1.0f, 0.045f, 0.0075f));
            m_scene.pointLights.push_back({position, {point[3], point[4], point[5]}, attenuation});
            m_settings.bias = spec.getVec3("bias", kPointBias * mapScale);
            const glm::vec3 target = spec.getVec3("point_target", 0.5f * (m_bounds.min + m_bounds.max));
            const float fov = static_cast<float>(spec.getNumberInRange("point_fov", 1.0, 179.0, 90.0));
            m_light.near = 0.5f;
            m_light.far = 30.0f;
            if (spec.has("point_range")) {
                const std::vector<float> range = spec.getNumbers("point_range", 2, "near far");
                m_light.near = range[0];
                m_light.far = range[1];
                if (!(m_light.near > 0.0f && m_light.far > m_light.near))
                    spec.reject("point_range", "point_range needs 0 < near < far");
            }
            m_light.perspective = true;
            m_light.lightSpaceMatrix = stoa::spotLightMatrix(position, target, fov, m_light.near, m_light.far);
        }
        if (m_settings.cascades.count > 0 && light != "sun")
            spec.reject("cascades", "cascades need light = sun (a point light has one perspective map)");
        m_light.sceneMin = m_bounds.min;
        m_light.sceneMax = m_bounds.max;
        if (m_settings.cascades.count > 0) loadCascadeProgram();
    }

    void render(glm::ivec2 size) override {
        m_renderer->render(m_scene, m_cameras.active(), size, m_light, m_settings);
    }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    bool keyPressed(unsigned char key) override {
        // Not 's': the first-person camera walks backwards with it.
        if (key == 'o') {
            m_settings.enabled = !m_settings.enabled;
            std::printf("shadows %s\n", m_settings.enabled ? "on" : "off");
        } else if (key == 'p') {
            m_settings.pcf = static_cast<stoa::PcfMode>((static_cast<int>(m_settings.pcf) + 1) % 3);
            std::printf("PCF: %s\n", stoa::toString(m_settings.pcf));
        } else if (key == 'm') {
            m_settings.showMap = !m_settings.showMap;
        } else if (key == 'n') {   // not 'c': the first-person camera goes down with it
            if (m_light.perspective) {
                std::printf("cascades are for the sun; this case has a point light\n");
                return true;
            }
            m_settings.cascades.count = m_settings.cascades.count > 0 ? 0 : m_cascadeCountOn;
            if (m_settings.cascades.count > 0) loadCascadeProgram();
            std::printf("cascades: %d\n", m_settings.cascades.count);
        } else if (key == 'k') {
            m_settings.cascades.colors = !m_settings.cascades.colors;
        } else {
            return false;
        }
        return true;
    }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "depth_pass_both_faces") return lab05::checkDepthPassBothFaces(*m_depthProgram);
        if (spec.check == "slice_corners") return lab05::checkSliceCorners();
        if (spec.check == "splits_blend_the_schemes") return lab05::checkSplitsBlendTheSchemes();
        if (spec.check == "cascade_depth_reaches_occluders") return lab05::checkCascadeDepthReachesOccluders();
        if (spec.check == "cascade_holds_its_slice") return lab05::checkCascadeHoldsItsSlice();
        if (spec.check == "light_box_holds_the_scene") return lab05::checkLightBoxHoldsTheScene();
        if (spec.check == "texel_snapping") return lab05::checkTexelSnapping();
        return Lab::runCheck(spec);
    }

    std::vector<std::string> keyHelp() const override {
        return {"o            shadows on / off", "p            PCF: single tap, 2x2, 3x3",
                "m            show the shadow map (the cascades' maps) in a corner",
                "n            cascaded shadow maps on / off (the sun only)",
                "k            tint each cascade: red, green, blue, yellow from near to far"};
    }

private:
    // Loaded at the first case or key that asks for cascades: its student stubs
    // (cascades.glsl) must not make the other cases "not attempted".
    void loadCascadeProgram() {
        if (!m_cascadeProgram)
            m_cascadeProgram = &m_resources->loadProgram("shadows/shadowed.vert", "shadows/cascaded.frag");
        m_renderer->setCascadeProgram(m_cascadeProgram);
    }

    stoa::Scene m_scene;
    SceneBounds m_bounds{};
    stoa::CameraRig m_cameras;
    stoa::ShadowLight m_light;
    stoa::ShadowSettings m_settings;
    int m_cascadeCountOn = 4;   // what key n turns on
    std::unique_ptr<stoa::ShadowRenderer> m_renderer;
    stoa::LabResources* m_resources = nullptr;
    const stoa::Program* m_depthProgram = nullptr;
    const stoa::Program* m_cascadeProgram = nullptr;
};

} // namespace

int main(int argc, char** argv) {
    ShadowsLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
