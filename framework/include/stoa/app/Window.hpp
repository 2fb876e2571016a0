#pragma once
// A window with an OpenGL 3.3 core context (freeglut). GLUT allows one window
// per program, so this class allows one instance at a time.
//
//   stoa::Window window(argc, argv, {"Lab 01", 960, 640});
//   window.run(myHandler);     // returns when the window closes

#include <stoa/app/Input.hpp>

#include <glm/vec2.hpp>

#include <memory>
#include <string>

namespace stoa {

class GpuResources;

/// What a window reports to. Every callback has a default that does nothing.
class WindowHandler {
public:
    virtual ~WindowHandler() = default;
    /// Draw one frame into the default framebuffer of `size` pixels.
    virtual void display(glm::ivec2 size) = 0;
    /// Called at fixed steps of simulated time (FixedStepClock), with what is held.
    virtual void update(float seconds, const InputState& input) { (void)seconds; (void)input; }
    /// Every event, before the callbacks below; `input` already includes it.
    virtual void event(const InputEvent& event, const InputState& input) { (void)event; (void)input; }
    /// Shorthands for the common cases, called after event():
    /// a key below 256 went down (a character's key, lower case for letters; Tab, Enter,
    /// Backspace, Delete; 27 is Escape), before its Text event.
    virtual void keyPressed(unsigned char key, const InputState& input) { (void)key; (void)input; }
    virtual void mouseDragged(glm::vec2 deltaPixels, const InputState& input) { (void)deltaPixels; (void)input; }
    virtual void mouseWheel(int notches) { (void)notches; }
};

struct WindowOptions {
    std::string title = "Stoa";
    int width = 960;     // pixels of the drawable area
    int height = 640;
};

class Window {
public:
    /// Creates the window and its context and loads OpenGL. Throws std::runtime_error
    /// when no display is available or the context lacks OpenGL 3.3.
    Window(int& argc, char** argv, const WindowOptions& options);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    /// Runs the event loop until the window closes or requestClose() is called.
    /// An exception that escapes a handler's callback ends the loop and is
    /// rethrown here (it never unwinds through GLUT).
    void run(WindowHandler& handler);
    void requestClose();
    void setTitle(const std::string& title);
    glm::ivec2 size() const;
    /// Presents the frame just drawn (run() does this after display()).
    void swapBuffers();

    /// The event loop's state (input, clock, handler), owned here and reached
    /// by GLUT's plain-function callbacks while this window lives.
    struct State;

private:
    std::unique_ptr<State> m_state;
    std::unique_ptr<GpuResources> m_resources;   // the context's caches (stoa/gl/GpuResources.hpp)
};

} // namespace stoa
