#include <stoa/app/ImGuiLayer.hpp>

#include <stoa/core/Assert.hpp>

#include <GL/freeglut.h>
#include <imgui.h>
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
bool ImGuiLayer::feed(const InputEvent& event) {
    const int x = static_cast<int>(event.position.x), y = static_cast<int>(event.position.y);
    const int key = static_cast<int>(event.key);
    const ImGuiIO& io = ImGui::GetIO();
    switch (event.type) {
    case InputEvent::Type::KeyDown:
        if (key >= kFirstSpecialKey) ImGui_ImplGLUT_SpecialFunc(key - kFirstSpecialKey, x, y);
        else if (key < 32 || key == 127) ImGui_ImplGLUT_KeyboardFunc(static_cast<unsigned char>(key), x, y);
        return io.WantCaptureKeyboard;   // printable keys arrive as Text
    case InputEvent::Type::KeyUp:
        if (key >= kFirstSpecialKey) ImGui_ImplGLUT_SpecialUpFunc(key - kFirstSpecialKey, x, y);
        else ImGui_ImplGLUT_KeyboardUpFunc(static_cast<unsigned char>(key), x, y);
        return io.WantCaptureKeyboard;
    case InputEvent::Type::Text:
        if (event.character < 128) ImGui_ImplGLUT_KeyboardFunc(static_cast<unsigned char>(event.character), x, y);
        return io.WantTextInput;
    case InputEvent::Type::MouseDown:
    case InputEvent::Type::MouseUp:
        ImGui_ImplGLUT_MouseFunc(glutButton(event.button),
                                 event.type == InputEvent::Type::MouseDown ? GLUT_DOWN : GLUT_UP, x, y);
        return io.WantCaptureMouse;
    case InputEvent::Type::MouseMove:
        ImGui_ImplGLUT_MotionFunc(x, y);
        return io.WantCaptureMouse;
    case InputEvent::Type::Wheel:
        ImGui_ImplGLUT_MouseWheelFunc(0, event.wheel, x, y);
        return io.WantCaptureMouse;
    case InputEvent::Type::Resize:
        ImGui_ImplGLUT_ReshapeFunc(event.size.x, event.size.y);
        return false;
    }
    return false;
}

void ImGuiLayer::beginFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGLUT_NewFrame();
}

void ImGuiLayer::endFrame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

} // namespace stoa
