#include <stoa/app/Input.hpp>

namespace stoa {

const char* keyName(Key key) {
    static const char* const functionKeys[] = {"F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8", "F9", "F10", "F11", "F12"};
    static const char* const arrows[] = {"Left", "Up", "Right", "Down", "PageUp", "PageDown", "Home", "End", "Insert"};
    static const char* const modifiers[] = {"LeftShift", "RightShift", "LeftControl", "RightControl", "LeftAlt", "RightAlt"};
    // One static string per printable character.
    static char printable[128][2] = {};
    const int code = static_cast<int>(key);
    switch (key) {
    case Key::Backspace: return "Backspace";
    case Key::Tab: return "Tab";
    case Key::Enter: return "Enter";
    case Key::Escape: return "Escape";
    case Key::Space: return "Space";
    case Key::Delete: return "Delete";
    default: break;
    }
    if (code >= static_cast<int>(Key::F1) && code <= static_cast<int>(Key::F12)) return functionKeys[code - static_cast<int>(Key::F1)];
    if (code >= static_cast<int>(Key::Left) && code <= static_cast<int>(Key::Insert)) return arrows[code - static_cast<int>(Key::Left)];
    if (code >= static_cast<int>(Key::LeftShift) && code <= static_cast<int>(Key::RightAlt))
        return modifiers[code - static_cast<int>(Key::LeftShift)];
    if (code > 32 && code < 127) {
        printable[code][0] = static_cast<char>(code);
        return printable[code];
    }
    return "Unknown";
}

const char* eventTypeName(InputEvent::Type type) {
    switch (type) {
    case InputEvent::Type::KeyDown: return "KeyDown";
    case InputEvent::Type::KeyUp: return "KeyUp";
    case InputEvent::Type::Text: return "Text";
    case InputEvent::Type::MouseDown: return "MouseDown";
    case InputEvent::Type::MouseUp: return "MouseUp";
    case InputEvent::Type::MouseMove: return "MouseMove";
    case InputEvent::Type::Wheel: return "Wheel";
    case InputEvent::Type::Resize: return "Resize";
    }
    return "?";
}

} // namespace stoa
