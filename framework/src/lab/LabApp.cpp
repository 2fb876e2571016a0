#include <stoa/app/HeadlessContext.hpp>
#include <stoa/app/Window.hpp>
#include <stoa/camera/Camera.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/image/ImageCompare.hpp>
#include <stoa/render/TextureOverlay.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

namespace stoa {

namespace {

struct Options {
    bool list = false;
    bool listChecks = false;
    std::string check;           // --check NAME or all: run property checks headless
    bool info = false;
    bool help = false;
    std::string renderCase;      // headless
    std::string output;
    std::optional<HeadlessBackend> backend;
    std::string windowCase;      // window
    std::string screenshot;
    int view = 0;                // --view: 0 live, 1 yours, 2 reference, 3 difference (the 'g' key's views)
    std::string casesFile;       // --cases: read the cases from this manifest instead of the lab's
};

/// A GLSL stub still in place, reported like a C++ NotImplemented.
struct ShaderNotImplemented : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void printUsage(const LabBuildInfo& info, std::FILE* to) {
    std::fprintf(to,
                 "usage: lab%s [--case NAME] [--view live|yours|reference|difference] [--screenshot FILE]\n"
                 "       lab%s --render NAME --output FILE.png [--backend osmesa|egl]\n"
                 "       lab%s --check NAME|all [--backend osmesa|egl]\n"
                 "       lab%s --list | --list-checks | --info | --help\n"
                 "Any of them takes --cases FILE.ini: the cases from that manifest instead of the lab's\n"
                 "cases.ini (the grader's hidden cases).\n\n"
                 "Without --render or --check the lab opens a window; see docs/labs/%s.md.\n"
                 "Exit status: 0 done, 1 error, 2 bad command line, 3 not attempted (a stub is in place),\n"
                 "4 a property check does not hold.\n",
                 info.name, info.name, info.name, info.name, info.name);
}

Options parseOptions(int argc, char** argv) {
    Options options;
    auto value = [&](int& i) -> std::string {
        if (i + 1 >= argc) throw InputError("", 0, std::string(argv[i]) + " needs a value");
        return argv[++i];
    };
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--list") options.list = true;
        else if (arg == "--list-checks") options.listChecks = true;
        else if (arg == "--check") options.check = value(i);
        else if (arg == "--info") options.info = true;
        else if (arg == "--help" || arg == "-h") options.help = true;
        else if (arg == "--render") options.renderCase = value(i);
        else if (arg == "--output") options.output = value(i);
        else if (arg == "--backend") options.backend = parseHeadlessBackend(value(i));
        else if (arg == "--case") options.windowCase = value(i);
        else if (arg == "--screenshot") options.screenshot = value(i);
        else if (arg == "--view") {
            const std::string name = value(i);
            const char* const views[] = {"live", "yours", "reference", "difference"};
            options.view = -1;
            for (int v = 0; v < 4; ++v)
                if (name == views[v]) options.view = v;
            if (options.view < 0)
                throw InputError("", 0, "--view takes live, yours, reference or difference, not '" + name + "'");
        }
        else if (arg == "--cases") options.casesFile = value(i);
        else
            throw InputError("", 0, "unknown argument '" + arg +
                                        "' (valid: --case, --view, --screenshot, --render, --output, --backend, --check, "
                                        "--cases, --list, --list-checks, --info, --help)");
    }
    if (!options.renderCase.empty() && options.output.empty())
        throw InputError("", 0, "--render needs --output FILE.png");
    if (!options.check.empty() && (!options.renderCase.empty() || !options.output.empty()))
        throw InputError("", 0, "--check runs property checks; it takes no --render or --output");
    if (!options.check.empty() && (!options.windowCase.empty() || !options.screenshot.empty() || options.view))
        throw InputError("", 0, "--case, --view and --screenshot are for the window; --check runs headless");
    if (options.renderCase.empty() && !options.output.empty())
        throw InputError("", 0, "--output goes with --render");
    if (options.renderCase.empty() && options.check.empty() && options.backend)
        throw InputError("", 0, "--backend goes with --render or --check");
    if (!options.renderCase.empty() && (!options.windowCase.empty() || !options.screenshot.empty() || options.view))
        throw InputError("", 0, "--case, --view and --screenshot are for the window; --render renders headless");
    return options;
}

std::vector<std::filesystem::path> splitSearchPath(const char* joined) {
    std::vector<std::filesystem::path> folders;
    std::stringstream stream(joined);
    std::string folder;
    while (std::getline(stream, folder, '|'))
        if (!folder.empty()) folders.emplace_back(folder);
    return folders;
}

const CaseSpec& findCase(const LabManifest& manifest, const std::string& name) {
    if (const CaseSpec* spec = manifest.find(name)) return *spec;
    throw InputError(manifest.file, 0, "no case '" + name + "' (cases: " + manifest.caseNames() + ")");
}

void throwIfShaderStubs(const LabResources& resources) {
    for (const auto& program : resources.programs()) {
        if (program->stubs().empty()) continue;
        const ShaderStub& stub = program->stubs().front();
        throw ShaderNotImplemented(stub.function + " (" + stub.file + ":" + std::to_string(stub.line) + ")");
    }
}

// The picture of a case whose scene is loaded: rendered at the case's size into
// an offscreen target, as `--render` writes it and the grader compares it.
// Throws NotImplemented or ShaderNotImplemented while a stub is in place.
Image renderCaseImage(Lab& lab, const LabResources& resources, const CaseSpec& spec) {
    Framebuffer target(spec.width, spec.height, FramebufferOptions{});
    target.bind();
    lab.render({spec.width, spec.height});
    throwIfShaderStubs(resources);
    Image image = target.readColor();
    Framebuffer::bindDefault();
    return image;
}

// Runs one property check and prints its verdict as one line (the grader shows
// the last line of output as the case's reason). 0 when it holds, else kExitCheckFailed.
// (A check runs C++ only: the GLSL stubs of the lab's programs do not stop it.)
int runOneCheck(Lab& lab, const CaseSpec& spec) {
    spec.requireAllKeysUsed();
    const CheckResult result = lab.runCheck(spec);
    std::printf("check %s: %s: %s\n", spec.name.c_str(), result.holds ? "holds" : "does not hold",
                result.message.c_str());
    std::fflush(stdout);
    return result.holds ? kExitOk : kExitCheckFailed;
}

// --check NAME|all: the lab's property checks, headless, each with its verdict.
int runChecks(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options) {
    std::vector<const CaseSpec*> selected;
    for (const CaseSpec& spec : manifest.cases)
        if (!spec.check.empty() && (options.check == "all" || spec.name == options.check)) selected.push_back(&spec);
    if (selected.empty()) {
        std::string checks;
        for (const CaseSpec& spec : manifest.cases)
            if (!spec.check.empty()) checks += (checks.empty() ? "" : ", ") + spec.name;
        throw InputError(manifest.file, 0,
                         "no property check '" + options.check + "' (checks: " + (checks.empty() ? "none" : checks) +
                             "; 'all' runs every one)");
    }
    HeadlessContext context(options.backend);
    enableDebugOutput();
    LabResources resources(splitSearchPath(info.shaderPath));
    lab.initialize(resources);
    int failed = 0, notAttempted = 0;
    for (const CaseSpec* spec : selected) {
        try {
            if (runOneCheck(lab, *spec) != kExitOk) ++failed;
        } catch (const NotImplemented& stub) {
            std::printf("check %s: not attempted: not implemented: %s\n", spec->name.c_str(), stub.function().c_str());
            ++notAttempted;
        }
    }
    if (selected.size() > 1)
        std::printf("%zu of %zu checks hold\n", selected.size() - static_cast<std::size_t>(failed + notAttempted),
                    selected.size());
    return failed > 0 ? kExitCheckFailed : notAttempted > 0 ? kExitNotAttempted : kExitOk;
}

int renderHeadless(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options) {
    const CaseSpec& spec = findCase(manifest, options.renderCase);
    HeadlessContext context(options.backend);
    enableDebugOutput();
    LabResources resources(splitSearchPath(info.shaderPath));
    lab.initialize(resources);
    // A property check renders no picture: the exit status is the verdict.
    if (!spec.check.empty()) return runOneCheck(lab, spec);
    lab.loadCase(spec);
    spec.requireAllKeysUsed();

    renderCaseImage(lab, resources, spec).savePng(options.output);
    return kExitOk;
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
        if (!m_screenshot.empty() && ++m_framesDrawn == 2) saveScreenshot(size);
    }

    void renderLive(glm::ivec2 size) {
        try {
            m_lab.render(size);
            throwIfShaderStubs(m_resources);
            setStatus("");
        } catch (const NotImplemented& stub) {
            showProblem("not implemented: " + stub.function());
        } catch (const ShaderNotImplemented& stub) {
            showProblem(std::string("not implemented: ") + stub.what());
        }
    }

    // Every callback below runs student code (the cameras' move(), look(),
    // tumble() ... are lab 01's exercises) through runStudentCode(), as
    // renderLive() does, so that a stub shows "not implemented: ..." and the
    // window keeps running.
    void update(float seconds, const InputState& input) override {
        runStudentCode([&] { m_lab.activeCamera().update(input, seconds); });
    }

    void mouseDragged(glm::vec2 delta, const InputState& input) override {
        runStudentCode([&] { m_lab.activeCamera().mouseDragged(input, delta); });
    }

    void mouseWheel(int notches) override {
        runStudentCode([&] { m_lab.activeCamera().mouseWheel(notches); });
    }

    void keyPressed(unsigned char key, const InputState&) override {
        if (key == 27) {
            m_window.requestClose();
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
        std::printf("Lab %s (%s track)\n"
                    "  mouse        orbit: left tumble, middle or Shift+left track, right or Ctrl+left dolly, wheel dolly\n"
                    "               first person: hold right and drag to look\n"
                    "  W A S D      walk (first person); Space up, C or Ctrl down, Shift faster\n"
                    "  Tab          switch orbit / first-person camera\n"
                    "  1..9         jump to a graded case's view\n"
                    "  g            the case as the grader sees it: yours, the reference, the difference, back\n"
                    "  h            this help;  Esc quit\n"
                    "  Shaders reload by themselves when you save them.\n",
                    m_info.name, m_info.track);
        for (const std::string& line : m_lab.keyHelp()) std::printf("  %s\n", line.c_str());
        for (std::size_t i = 0; i < m_pictures.size() && i < 9; ++i)
            std::printf("  case %zu: %s\n", i + 1, m_pictures[i]->name.c_str());
        if (m_pictures.size() < m_manifest.cases.size())
            std::printf("  property checks (no picture): lab%s --check all\n", m_info.name);
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
            if (!gradeCurrentCase()) return;
            m_view = View::Yours;
        } else if (m_view == View::Yours) {
            m_view = m_reference.id() != 0 ? View::Reference : View::Live;
        } else if (m_view == View::Reference) {
            m_view = View::Difference;
        } else {
            m_view = View::Live;
        }
        static const char* const names[] = {"live", "yours", "reference", "difference"};
        std::printf("view: %s\n", names[static_cast<int>(m_view)]);
        m_window.setTitle(std::string("Stoa lab ") + m_info.name + " -- " + names[static_cast<int>(m_view)] +
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
            showProblem("not implemented: " + stub.function());
            return false;
        } catch (const ShaderNotImplemented& stub) {
            Framebuffer::bindDefault();
            showProblem(std::string("not implemented: ") + stub.what());
            return false;
        }
        m_yours = Texture2D::fromImage(yours, pictureOptions());
        m_reference = Texture2D();
        m_difference = Texture2D();
        const std::filesystem::path referencePath =
            paths::sourceDir() / "autograder" / "references" / m_info.name / (spec.name + ".png");
        std::printf("case %s: rendered at %dx%d from its own camera, as the grader does\n", spec.name.c_str(),
                    spec.width, spec.height);
        try {
            Image reference = Image::load(referencePath);
            CompareResult result = compareImages(yours, reference, spec.compare);
            std::printf("  %s: %s\n", result.passed ? "passes" : "fails", result.summary.c_str());
            m_reference = Texture2D::fromImage(reference, pictureOptions());
            if (result.sameSize)
                m_difference = Texture2D::fromImage(differenceHeatMap(yours, reference, result, spec.compare),
                                                    pictureOptions());
        } catch (const InputError& error) {
            std::printf("  no reference to compare with: %s\n", error.what());
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
        glViewport(0, 0, size.x, size.y);
        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
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
            m_inputProblem = "not implemented: " + stub.function();
        } catch (const ShaderNotImplemented& stub) {
            m_inputProblem = std::string("not implemented: ") + stub.what();
        }
        setStatus(m_frameProblem);
    }

    void showProblem(const std::string& problem) {
        glClearColor(0.25f, 0.05f, 0.05f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
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
        m_window.setTitle(std::string("Stoa lab ") + m_info.name + (status.empty() ? "" : " -- " + status));
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

    void saveScreenshot(glm::ivec2 size) {
        Image image(size.x, size.y, 4);
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
        image.flipVertically();
        image.savePng(m_screenshot);
        m_window.requestClose();
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
};

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
    windowOptions.title = std::string("Stoa lab ") + info.name;
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
        std::fprintf(stderr, "stoa: not implemented: %s\n", stub.function().c_str());
        if (!options.screenshot.empty()) return kExitNotAttempted;
    }
    if (options.screenshot.empty()) handler.printHelp();
    for (int view = 0; view < options.view; ++view) handler.nextView();
    window.run(handler);
    return handler.exitCode();
}

} // namespace

CheckResult Lab::runCheck(const CaseSpec& spec) {
    spec.reject("check", "this lab has no property check '" + spec.check + "'");
}

LabResources::LabResources(std::vector<std::filesystem::path> shaderSearchPath)
    : m_searchPath(std::move(shaderSearchPath)) {}

LabResources::~LabResources() = default;

Program& LabResources::loadProgram(const std::string& vertexFile, const std::string& fragmentFile) {
    m_programs.push_back(std::make_unique<Program>(Program::fromFiles(vertexFile, fragmentFile, m_searchPath)));
    return *m_programs.back();
}

int runLab(Lab& lab, const LabBuildInfo& info, int argc, char** argv) {
    try {
        Options options;
        try {
            options = parseOptions(argc, argv);
        } catch (const InputError& error) {
            std::fprintf(stderr, "lab%s: %s\n", info.name, error.what());
            printUsage(info, stderr);
            return kExitUsage;
        }
        if (options.help) {
            printUsage(info, stdout);
            return kExitOk;
        }
        if (options.info) {
            std::printf("lab=%s\ntrack=%s\n", info.name, info.track);
            return kExitOk;
        }
        // --cases replaces the lab's manifest (it does not add to it): the grader
        // renders each hidden case with the hidden manifest it lives in.
        const LabManifest manifest = loadManifest(options.casesFile.empty()
                                                      ? std::filesystem::path(info.labDirectory) / "cases.ini"
                                                      : std::filesystem::path(options.casesFile));
        if (!manifest.lab.empty() && manifest.lab != info.name)
            throw InputError(manifest.file, 0, "these are the cases of lab " + manifest.lab + ", not of lab " + info.name);
        if (options.list || options.listChecks) {
            for (const CaseSpec& spec : manifest.cases)
                if (spec.check.empty() == options.list) std::printf("%s\n", spec.name.c_str());
            return kExitOk;
        }
        if (!options.check.empty()) return runChecks(lab, info, manifest, options);
        if (!options.renderCase.empty() && !manifest.find(options.renderCase)) {
            std::fprintf(stderr, "lab%s: no case '%s' (cases: %s)\n", info.name, options.renderCase.c_str(),
                         manifest.caseNames().c_str());
            return kExitUsage;
        }
        if (!options.renderCase.empty()) return renderHeadless(lab, info, manifest, options);
        return runWindow(lab, info, manifest, options, argc, argv);
    } catch (const NotImplemented& stub) {
        std::fprintf(stderr, "stoa: not implemented: %s\n", stub.function().c_str());
        return kExitNotAttempted;
    } catch (const ShaderNotImplemented& stub) {
        std::fprintf(stderr, "stoa: not implemented: %s\n", stub.what());
        return kExitNotAttempted;
    } catch (const InputError& error) {
        std::fprintf(stderr, "lab%s: %s\n", info.name, error.what());
        return kExitError;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "lab%s: %s\n", info.name, error.what());
        return kExitError;
    }
}

} // namespace stoa
