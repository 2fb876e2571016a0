#include <stoa/app/ImGuiLayer.hpp>

#include <stoa/core/Assert.hpp>

#include <GL/freeglut.h>
#include <imgui.h>
#include <imgui_internal.h>   // the windows' rectangles, to hit-test a press (overPanel)
#include <backends/imgui_impl_glut.h>
#include <backends/imgui_impl_opengl3.h>

namespace stoa {

namespace {

bool g_live = false;

int glutButton(MouseButton button) {
    switch (button) {
    case MouseButton::Left: return GLUT_LEFT_BUTTON;
    case MouseButton::Middle: return GLUT_MIDDLE_BUTTON;
    case MouseButton::Right: return GLUT_RIGHT_BUTTON;
    }
    return GLUT_LEFT_BUTTON;
}

} // namespace

ImGuiLayer::ImGuiLayer(glm::ivec2 size) {
    STOA_ASSERT(!g_live, "ImGuiLayer(): one ImGuiLayer at a time (ImGui's backends keep global state). "
                         "Destroy the first before making another.");
    g_live = true;
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;   // no imgui.ini next to the lab
    ImGui::StyleColorsDark();
    ImGui_ImplGLUT_Init();
    ImGui_ImplOpenGL3_Init("#version 330 core");
    ImGui_ImplGLUT_ReshapeFunc(size.x, size.y);
}

ImGuiLayer::~ImGuiLayer() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGLUT_Shutdown();
    ImGui::DestroyContext();
    g_live = false;
}

// The window's events back into the GLUT backend's callbacks: its key codes
// are GLUT's (Key values from kFirstSpecialKey on are GLUT's special codes).
void ImGuiLayer::apply(const InputEvent& event) {
    const int x = static_cast<int>(event.position.x), y = static_cast<int>(event.position.y);
    const int key = static_cast<int>(event.key);
    switch (event.type) {
    case InputEvent::Type::KeyDown:
        if (key >= kFirstSpecialKey) ImGui_ImplGLUT_SpecialFunc(key - kFirstSpecialKey, x, y);
        else if (key < 32 || key == 127) ImGui_ImplGLUT_KeyboardFunc(static_cast<unsigned char>(key), x, y);
        break;   // printable keys arrive as Text
    case InputEvent::Type::KeyUp:
        if (key >= kFirstSpecialKey) ImGui_ImplGLUT_SpecialUpFunc(key - kFirstSpecialKey, x, y);
        else ImGui_ImplGLUT_KeyboardUpFunc(static_cast<unsigned char>(key), x, y);
        break;
    case InputEvent::Type::Text:
        if (event.character < 128) ImGui_ImplGLUT_KeyboardFunc(static_cast<unsigned char>(event.character), x, y);
        break;
    case InputEvent::Type::MouseDown:
    case InputEvent::Type::MouseUp:
        ImGui_ImplGLUT_MouseFunc(glutButton(event.button),
                                 event.type == InputEvent::Type::MouseDown ? GLUT_DOWN : GLUT_UP, x, y);
        break;
    case InputEvent::Type::MouseMove:
        ImGui_ImplGLUT_MotionFunc(x, y);
        break;
    case InputEvent::Type::Wheel:
        ImGui_ImplGLUT_MouseWheelFunc(0, event.wheel, x, y);
        break;
    case InputEvent::Type::Resize:
        ImGui_ImplGLUT_ReshapeFunc(event.size.x, event.size.y);
        break;
    }
}

// A held release, outside GLUT's callbacks: the backend's key-up functions ask
// glutGetModifiers(), which freeglut refuses there, so the key states are set
// here as the backend sets them (imgui_impl_glut.cpp, 1.86); the modifiers
// keep what the last callback read.
void ImGuiLayer::release(const InputEvent& event) {
    ImGuiIO& io = ImGui::GetIO();
    if (event.type == InputEvent::Type::MouseUp) {
        apply(event);   // the mouse function reads no modifiers
        return;
    }
    const int key = static_cast<int>(event.key);
    if (key >= kFirstSpecialKey) {
        const int index = key - kFirstSpecialKey + 256;
        if (index < IM_ARRAYSIZE(io.KeysDown)) io.KeysDown[index] = false;
        return;
    }
    const int c = key & 0xFF;
    io.KeysDown[c] = false;
    if (c >= 1 && c <= 26) io.KeysDown[c - 1 + 'a'] = io.KeysDown[c - 1 + 'A'] = false;
    else if (c >= 'a' && c <= 'z') io.KeysDown[c - 'a' + 'A'] = false;
    else if (c >= 'A' && c <= 'Z') io.KeysDown[c - 'A' + 'a'] = false;
}

bool ImGuiLayer::overPanel(glm::vec2 position) const {
    const ImGuiContext& context = *ImGui::GetCurrentContext();
    for (const ImGuiWindow* window : context.Windows)
        if (!window->Hidden && (window->Active || window->WasActive) &&
            window->OuterRectClipped.Contains(ImVec2(position.x, position.y)))
            return true;
    return false;
}

bool ImGuiLayer::feed(const InputEvent& event) {
    const ImGuiIO& io = ImGui::GetIO();
    const int button = static_cast<int>(event.button);
    switch (event.type) {
    case InputEvent::Type::MouseDown:
        m_pressFrame[button] = m_frames;
        m_pressTaken[button] = io.WantCaptureMouse || overPanel(event.position);
        apply(event);
        return m_pressTaken[button];
    case InputEvent::Type::MouseUp: {
        const bool taken = m_pressTaken[button] || io.WantCaptureMouse;
        m_pressTaken[button] = false;
        if (m_pressFrame[button] == m_frames) m_held.push_back({event, m_frames});   // ImGui has not seen the press yet
        else apply(event);
        return taken;
    }
    case InputEvent::Type::MouseMove:
        apply(event);
        return io.WantCaptureMouse || m_pressTaken[0] || m_pressTaken[1] || m_pressTaken[2];
    case InputEvent::Type::KeyDown:
        m_keyPressFrames.emplace_back(static_cast<int>(event.key), m_frames);
        apply(event);
        return io.WantCaptureKeyboard;
    case InputEvent::Type::KeyUp: {
        bool pressedThisFrame = false;
        for (auto it = m_keyPressFrames.begin(); it != m_keyPressFrames.end();)
            if (it->first == static_cast<int>(event.key)) {
                pressedThisFrame = pressedThisFrame || it->second == m_frames;
                it = m_keyPressFrames.erase(it);
            } else {
                ++it;
            }
        if (pressedThisFrame) m_held.push_back({event, m_frames});
        else apply(event);
        return io.WantCaptureKeyboard;
    }
    case InputEvent::Type::Text:
        apply(event);
        return io.WantTextInput;
    case InputEvent::Type::Wheel:
        apply(event);
        return io.WantCaptureMouse || overPanel(event.position);
    case InputEvent::Type::Resize:
        apply(event);
        return false;
    }
    return false;
}

void ImGuiLayer::beginFrame() {
    // Releases held back in an earlier frame: ImGui has seen their press now.
    std::vector<Held> stillHeld;
    for (const Held& held : m_held) {
        if (held.frame < m_frames) release(held.event);
        else stillHeld.push_back(held);
    }
    m_held.swap(stillHeld);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGLUT_NewFrame();
    ++m_frames;
}

void ImGuiLayer::endFrame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

} // namespace stoa
