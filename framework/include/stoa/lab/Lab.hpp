#pragma once
// What a lab app provides: its scene, how a graded case sets it up, and how a
// frame is drawn. The app lifecycle (command line, window, headless render,
// shader reload, stub detection) is runLab()'s (LabApp.hpp), the same for every lab.

#include <stoa/app/Input.hpp>
#include <stoa/lab/PropertyCheck.hpp>

#include <glm/vec2.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace stoa {

class Camera;
class CaseSpec;
class Program;

/// Loads the lab's GL resources and keeps the programs, so the app can reload
/// them when a file changes and report GLSL stubs that are still in place.
class LabResources {
public:
    explicit LabResources(std::vector<std::filesystem::path> shaderSearchPath);
    ~LabResources();

    /// Builds a program from two files looked up in the shader search path (the
    /// track's lab folders first, then shaders/). Throws InputError naming file and line.
    Program& loadProgram(const std::string& vertexFile, const std::string& fragmentFile);

    const std::vector<std::filesystem::path>& shaderSearchPath() const { return m_searchPath; }
    const std::vector<std::unique_ptr<Program>>& programs() const { return m_programs; }

private:
    std::vector<std::filesystem::path> m_searchPath;
    std::vector<std::unique_ptr<Program>> m_programs;
};

class Lab {
public:
    virtual ~Lab() = default;

    /// A GL context exists: load programs and meshes.
    virtual void initialize(LabResources& resources) = 0;
    /// Sets up the scene and camera of a graded case (also when a number key jumps
    /// to it in the window). Read case keys through `spec`'s getters.
    virtual void loadCase(const CaseSpec& spec) = 0;
    /// The window's 'g' renders the current case through loadCase(), which
    /// replaces what the keys changed in the live view (a chosen debug view,
    /// the lights' time). keepLiveView() is called before, restoreLiveView()
    /// when the window is back in the live view; a lab whose keys change more
    /// than its camera keeps that here.
    virtual void keepLiveView() {}
    virtual void restoreLiveView() {}
    /// Draws one frame into the bound framebuffer.
    virtual void render(glm::ivec2 size) = 0;

    /// The camera the window's mouse and keys drive.
    virtual Camera& activeCamera() = 0;
    /// Tab in the window: switch between the orbit and first-person cameras.
    virtual void toggleCamera() {}
    /// A key the app did not handle; return true when the lab used it.
    virtual bool keyPressed(unsigned char key) { (void)key; return false; }
    /// Every event of the window (keys down and up, special keys, mouse
    /// buttons, motion, wheel, text, resize), before the app's own handling of
    /// it; return true when the lab used it, and the app leaves it alone (no
    /// camera move, no app key; Escape still quits). Runs under the stub guard.
    virtual bool handleEvent(const InputEvent& event) { (void)event; return false; }
    /// Advances the lab's simulation by `seconds` of simulated time: called in
    /// the window at fixed steps (FixedStepClock), after the camera moved.
    /// Graded frames do not depend on it.
    virtual void update(float seconds) { (void)seconds; }
    /// Draws the lab's own controls into the window's UI panel (F1), between
    /// ImGui::Begin() and End(); nothing by default. Only in builds with Dear ImGui.
    virtual void drawUi() {}
    /// True to open the window with the UI panel shown (an editor); F1 still
    /// toggles it. Never for --screenshot, whose picture is the scene's.
    virtual bool uiPanelAtStart() const { return false; }
    /// Escape in the window: true to quit. An editor with unsaved edits says
    /// so and returns false; a second Escape then quits (its choice).
    virtual bool quitRequested() { return true; }
    /// Lines added to the window's key help, e.g. "f  toggle facet normals".
    virtual std::vector<std::string> keyHelp() const { return {}; }
    /// Runs the property check `spec.check` (a case with a `check` key, PropertyCheck.hpp),
    /// after initialize(), with a GL context current. A stub it calls throws
    /// NotImplemented as in render(). The default knows no check: InputError.
    virtual CheckResult runCheck(const CaseSpec& spec);
};

} // namespace stoa
