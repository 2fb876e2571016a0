#include <stoa/app/FixedStepClock.hpp>
#include <stoa/app/Window.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/gl/FunctionLoader.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/GpuResources.hpp>

#include <GL/freeglut.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <utility>
#include <stdexcept>

namespace stoa {

// GLUT's callbacks are plain functions; they reach the one live window's
// state through s_current (owned by the Window, set while it lives).
struct Window::State {
    Window* window = nullptr;
    WindowHandler* handler = nullptr;
    InputState input;
    glm::ivec2 size{0};
    bool haveMouse = false;
    FixedStepClock clock;
    std::chrono::steady_clock::time_point lastFrame;
    std::exception_ptr escaped;   // an exception a handler let out, rethrown by run()
};

namespace {

Window::State* s_current = nullptr;

// An exception must not unwind through freeglut's C frames. Each callback runs
// its handler here: an exception that escapes the handler ends the event loop,
// and Window::run() rethrows it to the program's own error handling.
template <typename Function>
void guarded(Function&& function) {
    if (s_current->escaped) return;
    try {
        function();
    } catch (...) {
        s_current->escaped = std::current_exception();
        glutLeaveMainLoop();
    }
}

// Sends one event to the handler (under the guard), with the state updated first.
void dispatch(const InputEvent& event) {
    guarded([&] { s_current->handler->event(event, s_current->input); });
}

Key normalizeKey(unsigned char key) {
    // With Ctrl held GLUT reports control codes (Ctrl+A = 1); map letters back.
    // Tab (9), Enter (13) and Backspace (8) are keys of their own, not Ctrl+I/M/H.
    if (key >= 1 && key <= 26 && key != 8 && key != 9 && key != 13) return static_cast<Key>('a' + key - 1);
    return keyOf(static_cast<char>(key));
}

// freeglut's special key codes, from kFirstSpecialKey on (Input.hpp's Key values).
Key specialKey(int glutKey) { return static_cast<Key>(kFirstSpecialKey + glutKey); }

void readModifiers() {
    const int modifiers = glutGetModifiers();
    s_current->input.shift = (modifiers & GLUT_ACTIVE_SHIFT) != 0;
    s_current->input.control = (modifiers & GLUT_ACTIVE_CTRL) != 0;
    s_current->input.alt = (modifiers & GLUT_ACTIVE_ALT) != 0;
}

InputEvent makeEvent(InputEvent::Type type) {
    InputEvent event;
    event.type = type;
    event.modifiers = s_current->input.modifiers();
    event.position = s_current->input.mouse;
    return event;
}

void onDisplay() {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - s_current->lastFrame).count();
    s_current->lastFrame = now;
    const int steps = s_current->clock.advance(elapsed);
    guarded([&] {
        for (int i = 0; i < steps; ++i)
            s_current->handler->update(static_cast<float>(s_current->clock.step()), s_current->input);
        s_current->handler->display(s_current->size);
    });
    glutSwapBuffers();
}

void onReshape(int width, int height) {
    s_current->size = {width, height};
    InputEvent event = makeEvent(InputEvent::Type::Resize);
    event.size = {width, height};
    dispatch(event);
}

void onKeyDown(unsigned char raw, int x, int y) {
    readModifiers();
    s_current->input.mouse = {x, y};
    const Key key = normalizeKey(raw);
    s_current->input.keys[static_cast<std::size_t>(key)] = true;
    InputEvent down = makeEvent(InputEvent::Type::KeyDown);
    down.key = key;
    dispatch(down);
    guarded([&] { s_current->handler->keyPressed(static_cast<unsigned char>(key), s_current->input); });
    if (raw >= 32 && raw != 127) {   // a character typed: after its key
        InputEvent text = makeEvent(InputEvent::Type::Text);
        text.character = raw;
        text.key = key;
        dispatch(text);
    }
}

void onKeyUp(unsigned char raw, int x, int y) {
    readModifiers();
    s_current->input.mouse = {x, y};
    const Key key = normalizeKey(raw);
    s_current->input.keys[static_cast<std::size_t>(key)] = false;
    InputEvent up = makeEvent(InputEvent::Type::KeyUp);
    up.key = key;
    dispatch(up);
}

// freeglut reports the modifier keys themselves as special keys, so held
// Shift and Ctrl are known between mouse events too.
void onSpecial(int glutKey, bool down, int x, int y) {
    InputState& input = s_current->input;
    switch (glutKey) {
    case GLUT_KEY_SHIFT_L:
    case GLUT_KEY_SHIFT_R: input.shift = down; break;
    case GLUT_KEY_CTRL_L:
    case GLUT_KEY_CTRL_R: input.control = down; break;
    case GLUT_KEY_ALT_L:
    case GLUT_KEY_ALT_R: input.alt = down; break;
    default: readModifiers(); break;
    }
    input.mouse = {x, y};
    const Key key = specialKey(glutKey);
    if (static_cast<int>(key) < kKeyCount) input.keys[static_cast<std::size_t>(key)] = down;
    InputEvent event = makeEvent(down ? InputEvent::Type::KeyDown : InputEvent::Type::KeyUp);
    event.key = key;
    dispatch(event);
}
void onSpecialDown(int key, int x, int y) { onSpecial(key, true, x, y); }
void onSpecialUp(int key, int x, int y) { onSpecial(key, false, x, y); }

void onMouse(int button, int buttonState, int x, int y) {
    readModifiers();
    const bool down = buttonState == GLUT_DOWN;
    s_current->input.mouse = {x, y};
    s_current->haveMouse = true;
    if (button == 3 || button == 4) {   // the wheel: a press and a release per notch
        if (!down) return;
        InputEvent wheel = makeEvent(InputEvent::Type::Wheel);
        wheel.wheel = button == 3 ? 1 : -1;
        dispatch(wheel);
        guarded([&] { s_current->handler->mouseWheel(wheel.wheel); });
        return;
    }
    MouseButton which = MouseButton::Left;
    if (button == GLUT_MIDDLE_BUTTON) which = MouseButton::Middle;
    else if (button == GLUT_RIGHT_BUTTON) which = MouseButton::Right;
    else if (button != GLUT_LEFT_BUTTON) return;
    s_current->input.buttons[static_cast<std::size_t>(which)] = down;
    InputEvent event = makeEvent(down ? InputEvent::Type::MouseDown : InputEvent::Type::MouseUp);
    event.button = which;
    dispatch(event);
}

void onMotion(int x, int y) {
    const glm::vec2 position(x, y);
    const glm::vec2 delta = position - s_current->input.mouse;
    const bool dragged = s_current->haveMouse;
    s_current->input.mouse = position;
    s_current->haveMouse = true;
    dispatch(makeEvent(InputEvent::Type::MouseMove));
    if (dragged) guarded([&] { s_current->handler->mouseDragged(delta, s_current->input); });
}

void onPassiveMotion(int x, int y) {
    s_current->input.mouse = {x, y};
    s_current->haveMouse = true;
    dispatch(makeEvent(InputEvent::Type::MouseMove));
}

void onIdle() { glutPostRedisplay(); }

} // namespace

Window::Window(int& argc, char** argv, const WindowOptions& options) {
    STOA_ASSERT(s_current == nullptr, "Window::Window(): GLUT supports one window per program; destroy the first one");
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

    m_resources = std::make_unique<GpuResources>();
    GpuResources::makeCurrent(m_resources.get());

    m_state = std::make_unique<State>();
    m_state->window = this;
    m_state->size = {options.width, options.height};
    s_current = m_state.get();
}

Window::~Window() {
    s_current = nullptr;
    m_resources.reset();   // its GL objects, while the window's context is alive
}

void Window::run(WindowHandler& handler) {
    m_state->handler = &handler;
    m_state->lastFrame = std::chrono::steady_clock::now();
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
    m_state->handler = nullptr;
    if (m_state->escaped) std::rethrow_exception(std::exchange(m_state->escaped, nullptr));
}

void Window::requestClose() { glutLeaveMainLoop(); }

void Window::setTitle(const std::string& title) { glutSetWindowTitle(title.c_str()); }

glm::ivec2 Window::size() const { return m_state->size; }

void Window::swapBuffers() { glutSwapBuffers(); }

} // namespace stoa
