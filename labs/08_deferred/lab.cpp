// Lab 08 app: the Acropolis at night with hundreds of small lights drifting over
// it (stoa/scene/WanderingLights.hpp), lit three ways by stoa::DeferredRenderer:
//   renderer = forward   every fragment loops over all the lights (the baseline; no student code)
//   renderer = volumes   the G-buffer (your g_buffer.glsl), then one sphere per light of
//                        radius lightReach() drawn with lightVolumeState()
//   renderer = tiled     the G-buffer, then one full-screen pass over the lists of
//                        buildTileLightLists()
// The scene is the Acropolis with an avenue of six more statues (acropolisAvenuePieces(),
// about 304,000 triangles), so that the geometry is at the scale deferred shading is made for.
//
// Case keys besides the camera's (CameraRig.hpp):
//   renderer = forward | volumes | tiled     (default volumes)
//   view = final | albedo | normals | positions | specular | overdraw | tiles
//                                 what the picture shows (default final); overdraw: how many
//                                 light volumes cover each pixel; tiles: each tile's light count
//   lights = n                    how many wandering lights, 0..1024 (default 256)
//   seed = n                      their paths and colours (default 1)
//   time = seconds                where they are on their paths, 0..1000 (default 0)
//   tile_size = pixels            8..64 (default 16)
//   extra_light = x y z  r g b    one more light at a fixed place (world metres, linear colour)
//   cutoff = c                    the brightness at which a light counts as gone, (0, 0.5] (default 1/64)
//   heat_scale = n                the count the heat maps show as white, 1..1024 (default 64)
// In the window: r switches renderer, v the view, p stops and starts the lights.

#include "checks.hpp"

#include <stoa/gl/Program.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/PieceDrawList.hpp>
#include <stoa/scene/WanderingLights.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

const std::vector<std::string> kRenderers{"forward", "volumes", "tiled"};
const std::vector<std::string> kViews{"final", "albedo", "normals", "positions", "specular", "overdraw", "tiles"};

class DeferredLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        const auto load = [&](const std::string& vertex, const std::string& fragment) -> const stoa::Program& {
            return resources.loadProgram(vertex, fragment);
        };
        const stoa::DeferredPrograms programs = stoa::DeferredPrograms::load(load);
        m_renderer = std::make_unique<stoa::DeferredRenderer>(programs);

        m_scene = std::make_unique<stoa::PieceDrawList>(stoa::acropolisAvenuePieces());
        std::printf("scene: %zu triangles in %zu draws\n", m_scene->triangleCount(), m_scene->items().size());
        std::fflush(stdout);   // before a stub's message: the grader reads the stub from the last line
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        const std::string renderer = spec.getChoice("renderer", kRenderers, std::string("volumes"));
        m_settings.mode = renderer == "forward" ? stoa::LightingMode::Forward
                          : renderer == "tiled" ? stoa::LightingMode::Tiled
                                                : stoa::LightingMode::Volumes;
        const std::string view = spec.getChoice("view", kViews, std::string("final"));
        for (std::size_t i = 0; i < kViews.size(); ++i)
            if (view == kViews[i]) m_settings.view = static_cast<stoa::DeferredView>(i);
        m_lightOptions.count = spec.getIntInRange("lights", 0, 1024, 256);
        m_lightOptions.seed = static_cast<std::uint32_t>(spec.getIntInRange("seed", 0, 1000000, 1));
        m_time = static_cast<float>(spec.getNumber("time", 0.0));
        if (!(m_time >= 0.0f && m_time <= 1000.0f)) spec.reject("time", "time must be from 0 to 1000 seconds");
        m_settings.tileSize = spec.getIntInRange("tile_size", 8, 64, 16);
        m_settings.cutoff = static_cast<float>(spec.getNumber("cutoff", 1.0 / 64.0));
        if (!(m_settings.cutoff > 0.0f && m_settings.cutoff <= 0.5f)) spec.reject("cutoff", "cutoff must be in (0, 0.5]");
        m_settings.heatScale = static_cast<float>(spec.getIntInRange("heat_scale", 1, 1024, 64));
        m_extraLight.reset();
        if (spec.has("extra_light")) {
            const std::vector<float> v = spec.getNumbers("extra_light", 6, "position x y z, colour r g b");
            stoa::PointLight light;
            light.position = {v[0], v[1], v[2]};
            light.color = {v[3], v[4], v[5]};
            light.attenuation = glm::vec3(1.0f, 1.0f, 5.0f);
            if (!(v[3] >= 0.0f && v[4] >= 0.0f && v[5] >= 0.0f)) spec.reject("extra_light", "the colour must not be negative");
            m_extraLight = light;
        }
        m_moving = false;
    }

    // 'g' in the window: the renderer, view, lights and camera chosen with the
    // keys survive the case's render.
    void keepLiveView() override { m_kept = LiveView{m_cameras, m_settings, m_lightOptions, m_time, m_extraLight, m_moving}; }
    void restoreLiveView() override {
        if (!m_kept) return;
        m_cameras = m_kept->cameras;
        m_settings = m_kept->settings;
        m_lightOptions = m_kept->lightOptions;
        m_time = m_kept->time;
        m_extraLight = m_kept->extraLight;
        m_moving = m_kept->moving;
        m_kept.reset();
    }

    void render(glm::ivec2 size) override {
        std::vector<stoa::PointLight> lights = stoa::wanderingLights(m_lightOptions, m_time);
        if (m_extraLight) lights.push_back(*m_extraLight);
        m_renderer->render(m_scene->items(), lights, m_lighting, m_cameras.active(), size, m_settings);
    }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "reach_solves_the_falloff") return lab08::checkReachSolvesTheFalloff();
        if (spec.check == "tile_ranges_hold_the_sphere") return lab08::checkTileRangesHoldTheSphere();
        if (spec.check == "tile_lists_match_the_ranges") return lab08::checkTileListsMatchTheRanges();
        return Lab::runCheck(spec);
    }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    bool keyPressed(unsigned char key) override {
        if (key == 'r') {
            const int next = (static_cast<int>(m_settings.mode) + 1) % 3;
            m_settings.mode = static_cast<stoa::LightingMode>(next);
            std::printf("renderer: %s\n", stoa::toString(m_settings.mode));
            return true;
        }
        if (key == 'v') {
            const int next = (static_cast<int>(m_settings.view) + 1) % static_cast<int>(kViews.size());
            m_settings.view = static_cast<stoa::DeferredView>(next);
            std::printf("view: %s\n", stoa::toString(m_settings.view));
            return true;
        }
        if (key == 'p') {
            m_moving = !m_moving;
            std::printf("lights %s\n", m_moving ? "moving" : "stopped");
            return true;
        }
        return false;
    }

    void update(float seconds) override {
        if (m_moving) m_time += seconds;
    }

    std::vector<std::string> keyHelp() const override {
        return {"r            switch renderer: forward (all lights per fragment) / light volumes / tiles",
                "v            switch view: final / albedo / normals / positions / specular / overdraw / tiles",
                "p            start and stop the lights"};
    }

private:
    stoa::CameraRig m_cameras;
    struct LiveView {
        stoa::CameraRig cameras;
        stoa::DeferredSettings settings;
        stoa::WanderingLightsOptions lightOptions;
        float time = 0.0f;
        std::optional<stoa::PointLight> extraLight;
        bool moving = false;
    };
    std::optional<LiveView> m_kept;   // the live view while 'g' shows the case
    std::unique_ptr<stoa::DeferredRenderer> m_renderer;
    std::unique_ptr<stoa::PieceDrawList> m_scene;
    stoa::DeferredSettings m_settings;
    stoa::SceneLighting m_lighting;
    stoa::WanderingLightsOptions m_lightOptions;
    std::optional<stoa::PointLight> m_extraLight;
    float m_time = 0.0f;
    bool m_moving = false;
};

} // namespace

int main(int argc, char** argv) {
    DeferredLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
