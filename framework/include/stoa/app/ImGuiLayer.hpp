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

#include <stoa/app/Input.hpp>

#include <glm/vec2.hpp>

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
};

} // namespace stoa
