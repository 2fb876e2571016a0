#pragma once
// Lab 10's app, shared by the lab's program (lab.cpp: the graded cases) and
// stoa-crowds (any world file in a window). Not a student file.
//
// Case keys besides the camera's (CameraRig.hpp):
//   world = FILE          a world in assets/crowds/ (or a path relative to the
//                         cases file's folder, or absolute)
//   steps = n             simulation steps run before the picture, 0..20000 (default 0)
//   view = top | camera | pose | maps
//            top:    straight down over the whole ground (default)
//            camera: through the case's camera
//            pose:   one agent type's model alone, posed on the CPU by your
//                    md2FramesAt() and blendMd2Frames(), through the case's camera
//            maps:   your heightAt() as grey and walkableAt() (red where blocked),
//                    sampled at every pixel over the footprint
//   region = x0 z0 x1 z1  maps: the part of the footprint shown (default: all of it)
//   trails = on | off     the agents' trails (default: on in top view)
//   shadows = on | off    (default on)
//   type = NAME           pose: the agent type (default: the world's first)
//   animation = NAME      pose: the animation (default run)
//   time = seconds        pose: how far into the animation, >= 0 (default 0)
//   fps = n               key frames per second of every animation, (0, 60] (default 8)
// In the window: space pauses, n steps once while paused, + and - change the
// speed, t shows the trails, v switches the view, a click on an agent selects it.

#include "checks.hpp"
#include "lab10.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/crowd/CrowdLab.hpp>
#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/crowd/CrowdXml.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/Lab.hpp>
#include <stoa/render/CrowdRenderer.hpp>
#include <stoa/render/TextureOverlay.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#if __has_include(<imgui.h>)
#include <imgui.h>
#define STOA_CROWD_APP_IMGUI 1
#endif

namespace stoa {

class CrowdApp : public Lab {
public:
    static constexpr int kMaxSteps = 20000;

    void initialize(LabResources& resources) override {
        const auto load = [&](const std::string& vertex, const std::string& fragment) -> const Program& {
            return resources.loadProgram(vertex, fragment);
        };
        m_programs = CrowdPrograms::load(load);
        m_imageProgram = &resources.loadProgram("basic/image.vert", "basic/image.frag");
        m_overlay = std::make_unique<TextureOverlay>();
        m_poseFrame = std::make_unique<FrameUniforms>();
    }

    void loadCase(const CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        const std::string views[] = {"top", "camera", "pose", "maps"};
        const std::string view = spec.getChoice("view", {"top", "camera", "pose", "maps"}, std::string("top"));
        for (int i = 0; i < 4; ++i)
            if (view == views[i]) m_view = static_cast<View>(i);
        const int steps = spec.getIntInRange("steps", 0, kMaxSteps, 0);
        m_options.trails = spec.getSwitch("trails", m_view == View::Top);
        m_options.shadows = spec.getSwitch("shadows", true);
        m_options.framesPerSecond = static_cast<float>(spec.getNumber("fps", 8.0));
        if (!(m_options.framesPerSecond > 0.0f && m_options.framesPerSecond <= 60.0f))
            spec.reject("fps", "fps must be in (0, 60] key frames per second");
        m_poseTime = static_cast<float>(spec.getNumber("time", 0.0));
        if (!(m_poseTime >= 0.0f && m_poseTime <= 3600.0f)) spec.reject("time", "time must be in [0, 3600] seconds");
        m_poseAnimation = spec.getString("animation", std::string("run"));
        m_poseType = spec.getString("type", std::string(""));
        m_region = glm::vec4(0.0f);
        if (spec.has("region")) {
            const std::vector<float> region = spec.getNumbers("region", 4, "the corners x0 z0 x1 z1 of the part shown");
            m_region = glm::vec4(region[0], region[1], region[2], region[3]);
            if (!(m_region.x < m_region.z && m_region.y < m_region.w))
                spec.reject("region", "region needs x0 < x1 and z0 < z1");
        }
        const std::filesystem::path world = resolveWorld(spec.getString("world"), spec);
        loadWorld(world, steps);
        if (!m_poseType.empty() && m_world.findType(m_poseType) < 0)
            spec.reject("type", "the world has no agent type '" + m_poseType + "'");
        if (m_view == View::Pose) {
            const AgentType& type = m_world.types[static_cast<std::size_t>(m_poseType.empty() ? 0 : m_world.findType(m_poseType))];
            const Md2Model model = loadMd2(type.model);
            if (!model.findAnimation(m_poseAnimation)) {
                std::string names;
                for (const Md2Animation& animation : model.animations) names += (names.empty() ? "" : ", ") + animation.name;
                spec.reject("animation", "the model of type '" + type.name + "' (" + type.model.filename().string() +
                                             ") has no animation '" + m_poseAnimation + "'; it has: " + names);
            }
        }
        m_selected = -1;
        m_framesDrawn = 0;
        m_poseMesh.reset();
        m_mapsTexture.reset();
    }

    /// Loads `world` and its maps (InputError on a bad file); the agents are
    /// placed and run `steps` steps when a view first needs them, so that the
    /// pose and maps views run none of the behaviour code.
    void loadWorld(const std::filesystem::path& world, int steps) {
        m_world = loadCrowdWorld(world);
        m_maps = loadGroundMaps(m_world.ground, m_world.file);
        m_steps = steps;
        m_simulation.reset();
        m_renderer.reset();
        m_poseModel.reset();
        m_accumulated = 0.0f;
    }

    void render(glm::ivec2 size) override {
        const float aspect = static_cast<float>(size.x) / static_cast<float>(std::max(size.y, 1));
        m_lastSize = size;
        ++m_framesDrawn;
        switch (m_view) {
        case View::Top:
            simulation();
            if (!m_renderer) m_renderer = std::make_unique<CrowdRenderer>(m_programs, *m_simulation);
            m_lastView = CrowdView::topDown(m_maps.collision.grid, aspect);
            {
                CrowdDrawOptions options = drawOptions();
                options.flatScenery = true;
                m_renderer->render(*m_simulation, m_lastView, size, options);
            }
            break;
        case View::Camera:
            simulation();
            if (!m_renderer) m_renderer = std::make_unique<CrowdRenderer>(m_programs, *m_simulation);
            m_lastView = cameraView(aspect);
            m_renderer->render(*m_simulation, m_lastView, size, drawOptions());
            break;
        case View::Pose: renderPose(size, aspect); break;
        case View::Maps: renderMaps(size); break;
        }
    }

    /// The crowd, placed and run the case's steps at the first call.
    CrowdSimulation& simulation() {
        if (!m_simulation) {
            m_simulation = std::make_unique<CrowdSimulation>(m_world, m_maps);
            m_simulation->advance(m_steps);
        }
        return *m_simulation;
    }

    Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    CheckResult runCheck(const CaseSpec& spec) override {
        if (spec.check == "heights_at_texel_centres") return lab10::checkHeightsAtTexelCentres();
        if (spec.check == "walkable_at_texels") return lab10::checkWalkableAtTexels();
        if (spec.check == "blended_normals_unit") return lab10::checkBlendedNormalsUnit();
        if (spec.check == "layers_first_that_fires") return lab10::checkLayersFirstThatFires();
        return Lab::runCheck(spec);
    }

    /// The window steps the crowd at fixed steps of its clock.
    void update(float seconds) override { stepAgents(seconds); }

    bool keyPressed(unsigned char key) override {
        switch (key) {
        case ' ':
            m_paused = !m_paused;
            std::printf("%s at %.2f s\n", m_paused ? "paused" : "running", simulation().seconds());
            return true;
        case 'n':
            if (!m_paused) return false;
            simulation().step();
            std::printf("step %lld\n", m_simulation->stepCount());
            return true;
        case '+':
        case '=':
            m_speed = std::min(m_speed * 2.0f, 16.0f);
            std::printf("speed x%g\n", m_speed);
            return true;
        case '-':
            m_speed = std::max(m_speed * 0.5f, 0.125f);
            std::printf("speed x%g\n", m_speed);
            return true;
        case 't':
            m_options.trails = !m_options.trails;
            std::printf("trails %s\n", m_options.trails ? "on" : "off");
            return true;
        case 'v': {
            const char* names[] = {"top", "camera", "pose", "maps"};
            m_view = static_cast<View>((static_cast<int>(m_view) + 1) % 4);
            std::printf("view: %s\n", names[static_cast<int>(m_view)]);
            return true;
        }
        default: return false;
        }
    }

    bool handleEvent(const InputEvent& event) override {
        if (event.type == InputEvent::Type::MouseDown) {
            m_pressAt = event.position;
            return false;
        }
        if (event.type != InputEvent::Type::MouseUp || !m_simulation || m_lastSize.x == 0) return false;
        if (glm::length(event.position - m_pressAt) > 3.0f) return false;   // a drag, not a click
        select(event.position);
        return false;
    }

    std::vector<std::string> keyHelp() const override {
        return {"space        pause and run the simulation", "n            one step while paused",
                "+ -          simulation speed", "t            trails on and off",
                "v            switch view: top / camera / pose / maps", "click        select an agent and print its state"};
    }

    void drawUi() override {
#ifdef STOA_CROWD_APP_IMGUI
        if (!m_simulation) return;
        const CrowdStatistics s = m_simulation->statistics();
        ImGui::Text("%.1f s, step %lld, speed x%g%s", m_simulation->seconds(), m_simulation->stepCount(), m_speed,
                    m_paused ? " (paused)" : "");
        ImGui::Text("agents %d living, %d carrying", s.living, s.carrying);
        ImGui::Text("samples %d on the ground, %d delivered; crumbs %d; attacks %d", s.samplesOnGround, s.delivered,
                    s.crumbs, s.attacks);
        if (m_selected >= 0) ImGui::Text("selected: %s", describe(static_cast<std::size_t>(m_selected)).c_str());
        ImGui::Checkbox("trails", &m_options.trails);
        ImGui::Checkbox("shadows", &m_options.shadows);
        ImGui::Checkbox("paused", &m_paused);
#endif
    }

private:
    enum class View { Top, Camera, Pose, Maps };

    void stepAgents(float seconds) {
        // The case's own state stays for the first two frames: --screenshot
        // saves the second one (LabWindow), which must match the headless picture.
        if (m_paused || !m_simulation || m_framesDrawn < 2) return;
        m_accumulated += seconds * m_speed;
        const float step = m_world.step;
        // At most 50 ms of stepping a frame, so that the window keeps answering: a
        // crowd that cannot keep up runs slower than real time (the backlog is dropped).
        using Clock = std::chrono::steady_clock;
        const Clock::time_point start = Clock::now();
        while (m_accumulated >= step) {
            const Clock::time_point before = Clock::now();
            m_simulation->step();
            m_accumulated -= step;
            const double took = std::chrono::duration<double>(Clock::now() - before).count();
            if (took > 0.1 && !m_warnedSlow) {
                m_warnedSlow = true;
                std::printf("the crowd steps slowly: one step of %zu agents took %.0f ms, so it runs slower than real "
                            "time (a denser crowd or a longer sight costs more per agent; docs/crowds-xml.md)\n",
                            m_simulation->agents().size(), took * 1000.0);
                std::fflush(stdout);
            }
            if (Clock::now() - start > std::chrono::milliseconds(50)) {
                m_accumulated = 0.0f;
                break;
            }
        }
    }

    static std::filesystem::path resolveWorld(const std::string& name, const CaseSpec& spec) {
        const std::filesystem::path path(name);
        if (path.is_absolute()) return path;
        const std::filesystem::path inAssets = paths::assetsDir() / "crowds" / path;
        if (std::filesystem::exists(inAssets)) return inAssets;
        const std::filesystem::path nextToCases = std::filesystem::path(spec.file).parent_path() / path;
        if (std::filesystem::exists(nextToCases)) return nextToCases;
        spec.reject("world", "no world file '" + name + "' in " + (paths::assetsDir() / "crowds").string() +
                                 " or next to the cases file");
    }

    CrowdDrawOptions drawOptions() const {
        CrowdDrawOptions options = m_options;
        options.selected = m_selected;
        return options;
    }

    CrowdView cameraView(float aspect) const {
        const Camera& camera = m_cameras.active();
        CrowdView view;
        view.view = camera.viewMatrix();
        view.projection = camera.projectionMatrix(aspect);
        view.eye = camera.eyePosition();
        return view;
    }

    void renderPose(glm::ivec2 size, float aspect) {
        const int type = m_poseType.empty() ? 0 : m_world.findType(m_poseType);
        if (!m_poseModel) {
            const AgentType& agentType = m_world.types[static_cast<std::size_t>(type)];
            m_poseModel = uploadMd2(agentType.model, agentType.skin, agentType.scale);
        }
        const Md2GpuModel& gpu = *m_poseModel;
        if (!m_poseMesh) {
            const Md2Animation* animation = gpu.model.findAnimation(m_poseAnimation);   // loadCase() checked it
            const CrowdFunctions& code = studentCode().crowds;
            const Md2FramePair frames = code.md2FramesAt(*animation, m_poseTime, m_options.framesPerSecond);
            if (frames.first < animation->first || frames.first >= animation->first + animation->count ||
                frames.second < animation->first || frames.second >= animation->first + animation->count) {
                throw std::out_of_range("md2FramesAt() returned frames " + std::to_string(frames.first) + " and " +
                                        std::to_string(frames.second) + " for '" + animation->name +
                                        "', whose frames are " + std::to_string(animation->first) + ".." +
                                        std::to_string(animation->first + animation->count - 1));
            }
            m_poseMesh = std::make_unique<GpuMesh>(md2PoseMesh(gpu.model, frames, code));
        }
        const CrowdView view = cameraView(aspect);
        CrowdDrawOptions options = m_options;
        const FrameBlock block = CrowdRenderer::frameBlock(view, options);
        m_poseFrame->update(block);
        m_poseFrame->bind();
        PassDescription pass = passInto(size);
        pass.clear.color = true;
        pass.clear.colorValue = glm::vec4(0.2f, 0.22f, 0.26f, 1.0f);
        pass.clear.depth = true;
        pass.state.cull = CullMode::None;
        beginPass(pass);
        const Program& program = *m_programs.scenery;
        program.use();
        program.set("uModel", glm::scale(glm::mat4(1.0f), glm::vec3(gpu.scale)));
        program.set("uNormalMatrix", glm::mat3(1.0f));
        program.set("uLightSpace", glm::mat4(1.0f));
        program.set("uShadows", false);
        program.set("uDiffuse", glm::vec3(1.0f));
        program.set("uHasTexture", true);
        program.set("uTexture", 0);
        gpu.skin.bind(0);
        m_poseMesh->draw();
    }

    void renderMaps(glm::ivec2 size) {
        if (!m_mapsTexture) {
            // The student's look-ups at every pixel's centre over the footprint,
            // +x to the right and +z down, like the maps' own images.
            const GroundMaps& maps = m_maps;
            const GroundGrid& grid = maps.collision.grid;
            const bool zoomed = m_region != glm::vec4(0.0f);
            const glm::vec2 corner0 = zoomed ? glm::vec2(m_region.x, m_region.y) : grid.footprintMin;
            const glm::vec2 corner1 = zoomed ? glm::vec2(m_region.z, m_region.w) : grid.footprintMax;
            const CrowdFunctions& code = studentCode().crowds;
            // Heights as grey over their range in the picture (a zoomed region
            // spans a few decimetres, which the whole range would flatten).
            std::vector<float> heights(static_cast<std::size_t>(size.x) * size.y);
            std::vector<std::uint8_t> walkable(heights.size());
            for (int y = 0; y < size.y; ++y) {
                for (int x = 0; x < size.x; ++x) {
                    const glm::vec2 xz = corner0 + (corner1 - corner0) * glm::vec2((x + 0.5f) / size.x, (y + 0.5f) / size.y);
                    const std::size_t i = static_cast<std::size_t>(y) * size.x + x;
                    heights[i] = code.heightAt(maps.heights, xz);
                    walkable[i] = code.walkableAt(maps.collision, xz) ? 1 : 0;
                }
            }
            const auto [lowest, highest] = std::minmax_element(heights.begin(), heights.end());
            const float low = *lowest, range = *highest - *lowest;
            Image image(size.x, size.y, 3);
            for (int y = 0; y < size.y; ++y) {
                for (int x = 0; x < size.x; ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * size.x + x;
                    const float grey = range > 1e-6f ? std::clamp((heights[i] - low) / range, 0.0f, 1.0f) : 0.5f;
                    const auto level = static_cast<std::uint8_t>(std::lround(40.0f + 200.0f * grey));
                    // Image rows run down from the top: row y shows z growing downwards.
                    image.setPixel(x, y, walkable[i] ? glm::u8vec4(level, level, level, 255)
                                                     : glm::u8vec4(std::min(255, level + 60), level / 3, level / 3, 255));
                }
            }
            TextureOptions options;
            options.mipmaps = false;
            options.linear = false;
            options.wrap = GL_CLAMP_TO_EDGE;
            m_mapsTexture = std::make_unique<Texture2D>(Texture2D::fromImage(image, options));
        }
        PassDescription pass = passInto(size, RenderState::overlay());
        pass.clear.color = true;
        beginPass(pass);
        m_mapsTexture->bind(0);
        m_imageProgram->use();
        m_imageProgram->set("uImage", 0);
        m_overlay->draw(*m_imageProgram, {0, 0, size.x, size.y});
    }

    /// The agent nearest the ray through the clicked pixel, within 1.5 m of it.
    void select(glm::vec2 pixel) {
        if (m_view != View::Top && m_view != View::Camera) return;
        const glm::vec4 viewport(0.0f, 0.0f, static_cast<float>(m_lastSize.x), static_cast<float>(m_lastSize.y));
        const glm::vec3 window(pixel.x, static_cast<float>(m_lastSize.y) - pixel.y, 0.0f);
        const glm::vec3 nearPoint = glm::unProject(window, m_lastView.view, m_lastView.projection, viewport);
        const glm::vec3 farPoint =
            glm::unProject(glm::vec3(window.x, window.y, 1.0f), m_lastView.view, m_lastView.projection, viewport);
        const glm::vec3 direction = glm::normalize(farPoint - nearPoint);
        int best = -1;
        float bestDistance = 1.5f;
        const std::vector<CrowdAgent>& agents = m_simulation->agents();
        for (std::size_t i = 0; i < agents.size(); ++i) {
            if (!agents[i].alive) continue;
            // Distance from the ray to the agent's middle, half a metre above its feet.
            const glm::vec3 centre(agents[i].position.x, agents[i].y + 0.5f, agents[i].position.y);
            const float along = glm::dot(centre - nearPoint, direction);
            const float distance = glm::length(centre - (nearPoint + along * direction));
            if (distance < bestDistance) {
                best = static_cast<int>(i);
                bestDistance = distance;
            }
        }
        m_selected = best;
        if (best < 0) std::printf("no agent there\n");
        else std::printf("%s\n", describe(static_cast<std::size_t>(best)).c_str());
        std::fflush(stdout);
    }

    std::string describe(std::size_t index) const {
        const CrowdAgent& agent = m_simulation->agents()[index];
        char text[256];
        std::snprintf(text, sizeof text, "agent %zu (%s): %s%s%s at (%.2f, %.2f)", index,
                      m_world.types[static_cast<std::size_t>(agent.type)].name.c_str(),
                      m_simulation->stateName(index).c_str(), agent.carrying ? ", carrying" : "",
                      agent.alive ? "" : ", eaten", agent.position.x, agent.position.y);
        return text;
    }

    CameraRig m_cameras;
    CrowdPrograms m_programs;
    const Program* m_imageProgram = nullptr;
    std::unique_ptr<TextureOverlay> m_overlay;
    CrowdWorld m_world;
    GroundMaps m_maps;
    int m_steps = 0;
    std::unique_ptr<CrowdSimulation> m_simulation;   // made when a view needs the agents
    std::unique_ptr<Md2GpuModel> m_poseModel;
    std::unique_ptr<CrowdRenderer> m_renderer;
    std::unique_ptr<GpuMesh> m_poseMesh;
    std::unique_ptr<Texture2D> m_mapsTexture;
    std::unique_ptr<FrameUniforms> m_poseFrame;   // made once the context exists
    CrowdDrawOptions m_options;
    View m_view = View::Top;
    std::string m_poseType;
    std::string m_poseAnimation = "run";
    float m_poseTime = 0.0f;
    glm::vec4 m_region{0.0f};   // maps: x0 z0 x1 z1, all zero for the whole footprint
    int m_selected = -1;
    int m_framesDrawn = 0;   // since the case was loaded
    bool m_paused = false;
    float m_speed = 1.0f;
    float m_accumulated = 0.0f;
    bool m_warnedSlow = false;   // the slow-step line is printed once
    glm::vec2 m_pressAt{0.0f};
    glm::ivec2 m_lastSize{0};
    CrowdView m_lastView;
};

} // namespace stoa
