#include <stoa/app/FixedStepClock.hpp>
#include <stoa/app/Window.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/gl/FunctionLoader.hpp>
#include <stoa/gl/OpenGL.hpp>

#include <GL/freeglut.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <utility>
#include <stdexcept>

namespace stoa {

namespace {

// GLUT's callbacks are plain functions; they reach the one live window here.
struct WindowState {
    Window* window = nullptr;
    WindowHandler* handler = nullptr;
    InputState input;
    glm::ivec2 size{0};
    bool haveMouse = false;
    FixedStepClock clock;
    std::chrono::steady_clock::time_point lastFrame;
    std::exception_ptr escaped;   // an exception a handler let out, rethrown by run()
};
WindowState* g_state = nullptr;

// An exception must not unwind through freeglut's C frames. Each callback runs
// its handler here: an exception that escapes the handler ends the event loop,
// and Window::run() rethrows it to the program's own error handling.
template <typename Function>
void guarded(Function&& function) {
    if (g_state->escaped) return;
    try {
        function();
    } catch (...) {
        g_state->escaped = std::current_exception();
        glutLeaveMainLoop();
    }
}

unsigned char normalizeKey(unsigned char key) {
    // With Ctrl held GLUT reports control codes (Ctrl+A = 1); map letters back.
    if (key >= 1 && key <= 26) return static_cast<unsigned char>('a' + key - 1);
    if (key >= 'A' && key <= 'Z') return static_cast<unsigned char>(key - 'A' + 'a');
    return key;
}

void readModifiers() {
    const int modifiers = glutGetModifiers();
    g_state->input.shift = (modifiers & GLUT_ACTIVE_SHIFT) != 0;
    g_state->input.control = (modifiers & GLUT_ACTIVE_CTRL) != 0;
    g_state->input.alt = (modifiers & GLUT_ACTIVE_ALT) != 0;
}

void onDisplay() {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - g_state->lastFrame).count();
    g_state->lastFrame = now;
    const int steps = g_state->clock.advance(elapsed);
    guarded([&] {
        for (int i = 0; i < steps; ++i)
            g_state->handler->update(static_cast<float>(g_state->clock.step()), g_state->input);
        g_state->handler->display(g_state->size);
    });
    glutSwapBuffers();
}

void onReshape(int width, int height) { g_state->size = {width, height}; }

void onKeyDown(unsigned char key, int, int) {
    readModifiers();
    const unsigned char normalized = normalizeKey(key);
    g_state->input.keys[normalized] = true;
    guarded([&] { g_state->handler->keyPressed(normalized, g_state->input); });
}

void onKeyUp(unsigned char key, int, int) {
    readModifiers();
    g_state->input.keys[normalizeKey(key)] = false;
}

// freeglut reports the modifier keys themselves as special keys, so held
// Shift and Ctrl are known between mouse events too.
void onSpecial(int key, bool down) {
    switch (key) {
    case GLUT_KEY_SHIFT_L:
    case GLUT_KEY_SHIFT_R: g_state->input.shift = down; break;
    case GLUT_KEY_CTRL_L:
    case GLUT_KEY_CTRL_R: g_state->input.control = down; break;
    case GLUT_KEY_ALT_L:
    case GLUT_KEY_ALT_R: g_state->input.alt = down; break;
    default: break;
    }
}
void onSpecialDown(int key, int, int) { onSpecial(key, true); }
void onSpecialUp(int key, int, int) { onSpecial(key, false); }

void onMouse(int button, int buttonState, int x, int y) {
    readModifiers();
    const bool down = buttonState == GLUT_DOWN;
    if ((button == 3 || button == 4) && down) {   // wheel
        guarded([&] { g_state->handler->mouseWheel(button == 3 ? 1 : -1); });
        return;
    }
    if (button == GLUT_LEFT_BUTTON) g_state->input.buttons[0] = down;
    if (button == GLUT_MIDDLE_BUTTON) g_state->input.buttons[1] = down;
    if (button == GLUT_RIGHT_BUTTON) g_state->input.buttons[2] = down;
    g_state->input.mouse = {x, y};
    g_state->haveMouse = true;
}

void onMotion(int x, int y) {
    const glm::vec2 position(x, y);
    if (g_state->haveMouse)
        guarded([&] { g_state->handler->mouseDragged(position - g_state->input.mouse, g_state->input); });
    g_state->input.mouse = position;
    g_state->haveMouse = true;
}

void onPassiveMotion(int x, int y) {
    g_state->input.mouse = {x, y};
    g_state->haveMouse = true;
}

void onIdle() { glutPostRedisplay(); }

} // namespace

Window::Window(int& argc, char** argv, const WindowOptions& options) {
    STOA_ASSERT(g_state == nullptr, "Window::Window(): GLUT supports one window per program; destroy the first one");
    STOA_ASSERT(options.width > 0 && options.height > 0, "Window::Window(): the size must be positive");
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY"))
        throw std::runtime_error("no display to open a window on ($DISPLAY is not set); "
                                 "render headless with --render, or run under xvfb-run");
    glutInit(&argc, argv);
    glutInitContextVersion(3, 3);
    glutInitContextProfile(GLUT_CORE_PROFILE);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DOUBLE | GLUT_DEPTH | GLUT_STENCIL);
    glutInitWindowSize(options.width, options.height);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutCreateWindow(options.title.c_str());
    gl::loadFunctions(gl::glxLoader(), "GLX window");

    g_state = new WindowState();
    g_state->window = this;
    g_state->size = {options.width, options.height};
}

Window::~Window() {
    delete g_state;
    g_state = nullptr;
}

void Window::run(WindowHandler& handler) {
    g_state->handler = &handler;
    g_state->lastFrame = std::chrono::steady_clock::now();
    glutDisplayFunc(onDisplay);
    glutReshapeFunc(onReshape);
    glutKeyboardFunc(onKeyDown);
    glutKeyboardUpFunc(onKeyUp);
    glutSpecialFunc(onSpecialDown);
    glutSpecialUpFunc(onSpecialUp);
    glutMouseFunc(onMouse);
    glutMotionFunc(onMotion);
    glutPassiveMotionFunc(onPassiveMotion);
    glutIdleFunc(onIdle);
    glutMainLoop();
    g_state->handler = nullptr;
    if (g_state->escaped) std::rethrow_exception(std::exchange(g_state->escaped, nullptr));
}

void Window::requestClose() { glutLeaveMainLoop(); }

void Window::setTitle(const std::string& title) { glutSetWindowTitle(title.c_str()); }

glm::ivec2 Window::size() const { return g_state->size; }

void Window::swapBuffers() { glutSwapBuffers(); }

} // namespace stoa
