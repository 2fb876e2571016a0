#pragma once
// Dear ImGui in a Stoa window: its GLUT and OpenGL 3 backends (Debian's
// libimgui-dev), fed from the window's InputEvents rather than from GLUT's
// callbacks, so that the window keeps its own event stream and the lab sees
// every event too.
//
//   ImGuiLayer ui;                      // after the Window: needs its context
//   ... in WindowHandler::event():  if (ui.feed(event)) return;   // the panel took it
//   ... in display():  draw the scene, then
//   ui.beginFrame();
//   ImGui::Begin("Stoa"); ImGui::Text("hello"); ImGui::End();
//   ui.endFrame();                      // draws over the frame
//
// One at a time (ImGui's backends keep global state).
//
// Dear ImGui 1.86 (Debian's) reads the buttons and keys once a frame, as
// states: a press and release that arrive between two frames would leave
// no trace (a quick click on a button, a quick key). The layer holds such a
// release back until ImGui has seen the press in one frame. A press on a
// panel is the panel's even when the last frame did not yet know the mouse
// was there (its windows are hit-tested where they were drawn), and so are
// the moves and the release that follow it.

#include <stoa/app/Input.hpp>

#include <glm/vec2.hpp>

#include <utility>
#include <vector>

namespace stoa {

class ImGuiLayer {
public:
    /// Creates the ImGui context and initialises both backends for the
    /// current window's context (GLSL 330 core), over `size` pixels.
    explicit ImGuiLayer(glm::ivec2 size);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    /// Passes an event on to ImGui. True when ImGui wants it for itself (the
    /// mouse over the panel, typing into a field): the app should not act on it.
    bool feed(const InputEvent& event);

    /// Starts the UI of a frame (ImGui::NewFrame() included): call ImGui's
    /// widget functions after it.
    void beginFrame();
    /// Draws the UI over the bound framebuffer. ImGui's OpenGL 3 backend saves
    /// the GL state it changes and restores it, so the StateCache stays right.
    void endFrame();

private:
    struct Held {
        InputEvent event;
        int frame;   // frames begun when it arrived
    };
    void apply(const InputEvent& event);
    void release(const InputEvent& event);
    bool overPanel(glm::vec2 position) const;

    int m_frames = 0;                  // beginFrame() calls so far
    int m_pressFrame[3] = {-1, -1, -1};   // per mouse button: m_frames when it last went down
    bool m_pressTaken[3] = {false, false, false};   // that press went to a panel
    std::vector<std::pair<int, int>> m_keyPressFrames;   // (key, m_frames) of keys down
    std::vector<Held> m_held;          // releases held back until ImGui saw their press
};

} // namespace stoa
