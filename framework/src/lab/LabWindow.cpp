#include "LabWindow.hpp"

#include "CaseComparison.hpp"
#include "HeadlessRender.hpp"
#include "ProgramName.hpp"

#include <stoa/app/ImGuiLayer.hpp>
#include <stoa/app/Window.hpp>
#include <stoa/camera/Camera.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/StudentPass.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/TextureOverlay.hpp>

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

namespace stoa::detail {

namespace {

// screenshots/NAME-N.png under the current folder, N the first number not yet
// taken (a second F12 never overwrites the first); the folder made if need be.
std::filesystem::path nextScreenshotPath(const std::string& name) {
    const std::filesystem::path folder = std::filesystem::absolute("screenshots");
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    for (int n = 1;; ++n) {
        const std::filesystem::path file = folder / (name + "-" + std::to_string(n) + ".png");
        if (!std::filesystem::exists(file, error)) return file;
    }
}

// A picture shown at about its size: no mipmaps, clamped.
TextureOptions pictureOptions() {
    TextureOptions options;
    options.mipmaps = false;
    options.wrap = GL_CLAMP_TO_EDGE;
    return options;
}

// The interactive app: the lab in a window with the cameras, case jumps and reload.
class LabWindow : public WindowHandler {
public:
    LabWindow(Lab& lab, Window& window, const LabBuildInfo& info, const LabManifest& manifest,
              LabResources& resources, std::string screenshot)
        : m_lab(lab), m_window(window), m_info(info), m_manifest(manifest), m_resources(resources),
          m_screenshot(std::move(screenshot)) {}

    void display(glm::ivec2 size) override {
        reloadChangedShaders();
        if (m_view != View::Live) {
            showPicture(size);
        } else {
            renderLive(size);
        }
        if (!m_uiDecided) {
            m_uiDecided = true;
            m_showUi = m_screenshot.empty() && m_lab.uiPanelAtStart();
        }
        if (m_showUi) drawUi(size);
        if (!m_screenshot.empty() && ++m_framesDrawn == 2) {
            saveScreenshot(size, m_screenshot);
            m_window.requestClose();
        }
        if (m_screenshotRequested) {
            m_screenshotRequested = false;
            const std::filesystem::path file = nextScreenshotPath(programName(m_info));
            saveScreenshot(size, file.string());
            std::printf("saved %s\n", file.string().c_str());
            std::fflush(stdout);
        }
    }

    // Every event goes to the UI panel first (when shown), then to the lab;
    // what the panel or the lab takes, the app leaves alone (but Escape quits). F1 shows the panel, F12 saves the
    // window as screenshots/labNN_name-N.png under the current folder (git ignores screenshots/).
    void event(const InputEvent& event, const InputState&) override {
        m_uiTookEvent = false;
        // F1 and F12 are the app's even while a panel's text field has the keyboard.
        if (event.type == InputEvent::Type::KeyDown && event.key == Key::F1) {
            m_showUi = !m_showUi;
            std::printf("ui panel %s\n", m_showUi ? "on" : "off");
            std::fflush(stdout);
            m_uiTookEvent = true;
            return;
        }
        if (event.type == InputEvent::Type::KeyDown && event.key == Key::F12) {
            m_screenshotRequested = true;
            m_uiTookEvent = true;
            return;
        }
        if (m_ui && m_showUi && m_ui->feed(event)) {
            m_uiTookEvent = true;
            return;
        }
        runStudentCode([&] { m_uiTookEvent = m_lab.handleEvent(event); });
    }

    void drawUi(glm::ivec2 size) {
        if (!m_ui) m_ui = std::make_unique<ImGuiLayer>(size);
        m_ui->beginFrame();
        ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_Always);
        // At least 280 x 120, and as large as what the lab adds (drawUi()) needs.
        ImGui::SetNextWindowSizeConstraints(ImVec2(280.0f, 120.0f), ImVec2(FLT_MAX, FLT_MAX));
        ImGui::Begin("Stoa", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::Text("%s (%s)", programName(m_info).c_str(), m_info.track);
        ImGui::Text("case %s", m_pictures[m_caseIndex]->name.c_str());
        ImGui::Text("%.1f ms per frame", 1000.0f / std::max(ImGui::GetIO().Framerate, 1.0f));
        runStudentCode([&] { m_lab.drawUi(); });   // a stub there leaves the panel whole
        ImGui::End();
        m_ui->endFrame();
    }

    void renderLive(glm::ivec2 size) {
        try {
            m_lab.render(size);
            throwIfShaderStubs(m_resources);
            setStatus("");
        } catch (const NotImplemented& stub) {
            showProblem(notImplementedText(stub.describe(m_info.name)));
        } catch (const ShaderNotImplemented& stub) {
            showProblem(notImplementedText(stub.what()));
        } catch (const GlStateChanged& changed) {   // the window stays, with what to fix
            StateCache::current().forget();
            showProblem(changed.what());
        }
    }

    // Every callback below runs student code (the cameras' move(), look(),
    // tumble() ... are lab 01's exercises) through runStudentCode(), as
    // renderLive() does, so that a stub shows "not implemented: ..." and the
    // window keeps running.
    void update(float seconds, const InputState& input) override {
        runStudentCode([&] { m_lab.activeCamera().update(input, seconds); });
        runStudentCode([&] { m_lab.update(seconds); });
    }

    void mouseDragged(glm::vec2 delta, const InputState& input) override {
        if (m_uiTookEvent) return;
        runStudentCode([&] { m_lab.activeCamera().mouseDragged(input, delta); });
    }

    void mouseWheel(int notches) override {
        if (m_uiTookEvent) return;
        runStudentCode([&] { m_lab.activeCamera().mouseWheel(notches); });
    }

    void keyPressed(unsigned char key, const InputState&) override {
        if (m_uiTookEvent && key != 27) return;   // Escape always quits
        if (key == 27) {
            bool quit = true;
            runStudentCode([&] { quit = m_lab.quitRequested(); });
            if (quit) m_window.requestClose();
        } else if (key >= '1' && key <= '9') {
            const std::size_t index = static_cast<std::size_t>(key - '1');
            if (index < m_pictures.size()) {
                m_caseIndex = index;
                m_view = View::Live;
                runStudentCode([&] { m_lab.loadCase(*m_pictures[index]); });
                std::printf("case %zu: %s -- %s\n", index + 1, m_pictures[index]->name.c_str(),
                            m_pictures[index]->description.c_str());
            }
        } else if (key == '\t') {
            runStudentCode([&] { m_lab.toggleCamera(); });
        } else if (key == 'g') {
            cycleView();
        } else if (key == 'h') {
            printHelp();
        } else {
            // The lab's own keys run student code too (a stub may throw). Unused keys
            // are fine: the cameras read W/A/S/D/C/Space as held keys.
            runStudentCode([&] { m_lab.keyPressed(key); });
        }
        std::fflush(stdout);
    }

    void printHelp() const {
        std::printf("%s (%s track)\n"
                    "  mouse        orbit: left tumble, middle or Shift+left track, right or Ctrl+left dolly, wheel dolly\n"
                    "               first person: hold right and drag to look\n"
                    "  W A S D      walk (first person); Space up, C or Ctrl down, Shift faster\n"
                    "  Tab          switch orbit / first-person camera\n"
                    "  1..9         jump to a graded case's view\n"
                    "  g            the case as the grader sees it: yours, the reference, the difference, back\n"
                    "  F1           the UI panel;  F12 save the window in screenshots/%s-N.png\n"
                    "  h            this help;  Esc quit\n"
                    "  Shaders reload by themselves when you save them.\n",
                    programName(m_info).c_str(), m_info.track, programName(m_info).c_str());
        for (const std::string& line : m_lab.keyHelp()) std::printf("  %s\n", line.c_str());
        for (std::size_t i = 0; i < m_pictures.size() && i < 9; ++i)
            std::printf("  case %zu: %s\n", i + 1, m_pictures[i]->name.c_str());
        if (m_pictures.size() < m_manifest.cases.size())
            std::printf("  property checks (no picture): %s --check all\n", programName(m_info).c_str());
    }

    int exitCode() const { return m_exitCode; }

    /// The case the window shows (and 'g' grades): the first one, or the one --case named.
    void setCase(std::size_t index) { m_caseIndex = index; }
    /// The 'g' key: live -> yours -> reference -> difference -> live.
    void nextView() { cycleView(); }

private:
    // What the window shows: the live scene, or one of the pictures of the
    // current case that the grader compares (rendered at the case's size).
    enum class View { Live, Yours, Reference, Difference };

    void cycleView() {
        if (m_view == View::Live) {
            runStudentCode([&] { m_lab.keepLiveView(); });   // loadCase() below replaces it
            if (!gradeCurrentCase()) {
                runStudentCode([&] { m_lab.restoreLiveView(); });
                return;
            }
            m_view = View::Yours;
        } else if (m_view == View::Yours) {
            m_view = m_reference.id() != 0 ? View::Reference : View::Live;
        } else if (m_view == View::Reference) {
            m_view = View::Difference;
        } else {
            m_view = View::Live;
        }
        if (m_view == View::Live) runStudentCode([&] { m_lab.restoreLiveView(); });   // as the keys left it
        static const char* const names[] = {"live", "yours", "reference", "difference"};
        std::printf("view: %s\n", names[static_cast<int>(m_view)]);
        m_window.setTitle(windowTitle(m_info) + " -- " + names[static_cast<int>(m_view)] +
                          (m_view == View::Live ? "" : " -- case " + m_pictures[m_caseIndex]->name));
    }

    // Renders the current case at its size from its own camera (what
    // `--render` writes), compares it with its reference as stoa-grade does, and
    // keeps the three pictures as textures. False when the case cannot render.
    bool gradeCurrentCase() {
        const CaseSpec& spec = *m_pictures[m_caseIndex];
        Image yours;
        try {
            m_lab.loadCase(spec);
            yours = renderCaseImage(m_lab, m_resources, spec);
        } catch (const NotImplemented& stub) {
            Framebuffer::bindDefault();
            showProblem(notImplementedText(stub.describe(m_info.name)));
            return false;
        } catch (const ShaderNotImplemented& stub) {
            Framebuffer::bindDefault();
            showProblem(notImplementedText(stub.what()));
            return false;
        } catch (const GlStateChanged& changed) {
            StateCache::current().forget();
            Framebuffer::bindDefault();
            showProblem(changed.what());
            return false;
        }
        m_yours = Texture2D::fromImage(yours, pictureOptions());
        m_reference = Texture2D();
        m_difference = Texture2D();
        std::printf("case %s: rendered at %dx%d from its own camera, as the grader does\n", spec.name.c_str(),
                    spec.width, spec.height);
        const CaseComparison comparison = compareWithReference(
            yours, spec, m_info.referenceDirectory ? m_info.referenceDirectory : "");
        if (comparison.haveReference) {
            std::printf("  %s: %s\n", comparison.result.passed ? "passes" : "fails", comparison.result.summary.c_str());
            m_reference = Texture2D::fromImage(comparison.reference, pictureOptions());
            if (comparison.result.sameSize) m_difference = Texture2D::fromImage(comparison.difference, pictureOptions());
        } else {
            std::printf("  no reference to compare with: %s\n", comparison.problem.c_str());
        }
        std::fflush(stdout);
        return true;
    }

    // The picture of the current view, as large as fits the window at its aspect ratio.
    void showPicture(glm::ivec2 size) {
        if (!m_imageProgram) {
            m_imageProgram = std::make_unique<Program>(
                Program::fromFiles("basic/image.vert", "basic/image.frag", m_resources.shaderSearchPath()));
            m_overlay = std::make_unique<TextureOverlay>();
        }
        const Texture2D& picture =
            m_view == View::Yours ? m_yours : m_view == View::Reference ? m_reference : m_difference;
        STOA_GL_CALL(glViewport(0, 0, size.x, size.y));
        STOA_GL_CALL(glClearColor(0.1f, 0.1f, 0.1f, 1.0f));
        STOA_GL_CALL(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
        if (picture.id() == 0) return;   // a difference of pictures of different sizes
        const float scale = std::min(static_cast<float>(size.x) / picture.width(),
                                     static_cast<float>(size.y) / picture.height());
        const glm::ivec2 shown(static_cast<int>(picture.width() * scale), static_cast<int>(picture.height() * scale));
        picture.bind(0);
        m_imageProgram->use();
        m_imageProgram->set("uImage", 0);
        m_overlay->draw(*m_imageProgram, {(size.x - shown.x) / 2, (size.y - shown.y) / 2, shown.x, shown.y});
    }

    // Runs student code from an input callback. A stub's problem goes to the
    // terminal and the title bar (after the frame's own problem, if it has one);
    // the window goes on with the next event.
    template <typename Function>
    void runStudentCode(Function&& function) {
        try {
            function();
            return;
        } catch (const NotImplemented& stub) {
            m_inputProblem = notImplementedText(stub.describe(m_info.name));
        } catch (const ShaderNotImplemented& stub) {
            m_inputProblem = notImplementedText(stub.what());
        }
        setStatus(m_frameProblem);
    }

    void showProblem(const std::string& problem) {
        STOA_GL_CALL(glClearColor(0.25f, 0.05f, 0.05f, 1.0f));
        STOA_GL_CALL(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
        setStatus(problem);
        if (!m_screenshot.empty()) m_exitCode = kExitNotAttempted;
    }

    // The title bar shows the frame's problem and the last one an input callback
    // met (a stub met there stays on show: C++ code does not change while the
    // program runs); the terminal gets each problem once.
    void setStatus(const std::string& frameProblem) {
        m_frameProblem = frameProblem;
        std::string status = frameProblem;
        if (!m_inputProblem.empty() && m_inputProblem != frameProblem)
            status += (status.empty() ? "" : "; ") + m_inputProblem;
        reportOnce(frameProblem);
        reportOnce(m_inputProblem);
        if (status == m_status) return;
        m_status = status;
        m_window.setTitle(windowTitle(m_info) + (status.empty() ? "" : " -- " + status));
    }

    void reportOnce(const std::string& problem) {
        if (problem.empty() || !m_reported.insert(problem).second) return;
        std::fprintf(stderr, "stoa: %s\n", problem.c_str());
    }

    void reloadChangedShaders() {
        const auto now = std::chrono::steady_clock::now();
        if (now - m_lastReloadCheck < std::chrono::milliseconds(500)) return;
        m_lastReloadCheck = now;
        for (const auto& program : m_resources.programs()) {
            if (program->reloadIfChanged()) std::printf("shaders reloaded\n");
            else if (!program->lastError().empty() && program->lastError() != m_lastShaderError) {
                m_lastShaderError = program->lastError();
                std::fprintf(stderr, "%s\n(keeping the last program that compiled)\n", m_lastShaderError.c_str());
            }
        }
        std::fflush(stdout);
    }

    static void saveScreenshot(glm::ivec2 size, const std::string& file) {
        Image image(size.x, size.y, 4);
        STOA_GL_CALL(glReadBuffer(GL_BACK));
        STOA_GL_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
        STOA_GL_CALL(glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, image.data()));
        image.flipVertically();
        image.savePng(file);
    }

    Lab& m_lab;
    Window& m_window;
    const LabBuildInfo& m_info;
    const LabManifest& m_manifest;
    const std::vector<const CaseSpec*> m_pictures = m_manifest.pictureCases();   // keys 1..9 jump to these
    LabResources& m_resources;
    std::string m_screenshot;
    std::string m_status = "-";
    std::string m_inputProblem;       // the last stub an input callback met ("" when none)
    std::string m_frameProblem;       // the stub the last frame met ("" when none)
    std::set<std::string> m_reported;   // problems already printed to the terminal
    std::string m_lastShaderError;
    std::chrono::steady_clock::time_point m_lastReloadCheck = std::chrono::steady_clock::now();
    int m_framesDrawn = 0;
    int m_exitCode = kExitOk;
    std::size_t m_caseIndex = 0;
    View m_view = View::Live;
    Texture2D m_yours, m_reference, m_difference;
    std::unique_ptr<Program> m_imageProgram;
    std::unique_ptr<TextureOverlay> m_overlay;
    std::unique_ptr<ImGuiLayer> m_ui;   // made at the first F1
    bool m_showUi = false;
    bool m_uiDecided = false;   // uiPanelAtStart() asked (at the first frame, after the first case loaded)
    bool m_uiTookEvent = false;         // the panel or the lab used the event being handled
    bool m_screenshotRequested = false;
};

} // namespace

int runWindow(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options, int argc,
              char** argv) {
    const std::vector<const CaseSpec*> pictures = manifest.pictureCases();
    if (pictures.empty()) throw InputError(manifest.file, 0, "no case with a picture to show in the window");
    const CaseSpec& first = options.windowCase.empty() ? *pictures.front() : findCase(manifest, options.windowCase);
    if (!first.check.empty())
        throw InputError(manifest.file, first.line,
                         "case '" + first.name + "' is a property check, with no picture: run it with --check " +
                             first.name);
    WindowOptions windowOptions;
    windowOptions.title = windowTitle(info);
    if (!options.screenshot.empty()) {
        windowOptions.width = first.width;    // the screenshot matches the headless render
        windowOptions.height = first.height;
    }
    Window window(argc, argv, windowOptions);
    enableDebugOutput();
    LabResources resources(splitSearchPath(info.shaderPath));
    lab.initialize(resources);
    LabWindow handler(lab, window, info, manifest, resources, options.screenshot);
    handler.setCase(static_cast<std::size_t>(std::find(pictures.begin(), pictures.end(), &first) - pictures.begin()));
    try {
        lab.loadCase(first);
        first.requireAllKeysUsed();
    } catch (const NotImplemented& stub) {
        std::fprintf(stderr, "%s\n", notImplementedLine(stub.describe(info.name)).c_str());
        if (!options.screenshot.empty()) return kExitNotAttempted;
    }
    if (options.screenshot.empty()) handler.printHelp();
    for (int view = 0; view < options.view; ++view) handler.nextView();
    window.run(handler);
    return handler.exitCode();
}

} // namespace stoa::detail
