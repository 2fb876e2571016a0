#pragma once
// What the user does (InputEvent, one per key, button, motion, wheel notch,
// character typed or resize) and what they are holding right now (InputState,
// as the window last reported it).

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>

namespace stoa {

enum class MouseButton { Left = 0, Middle = 1, Right = 2 };

/// A key on the keyboard. Keys that type a character are that character,
/// lower case for letters ('a', '1', ' ', '\t'), with Escape 27, Enter 13,
/// Backspace 8 and Delete 127; the others come from kFirstSpecialKey on.
enum class Key : int {
    Unknown = 0,
    Backspace = 8,
    Tab = 9,
    Enter = 13,
    Escape = 27,
    Space = 32,
    Delete = 127,
    F1 = 257, F2, F3, F4, F5, F6, F7, F8, F9, F10, F11, F12,   // 257..268
    Left = 356, Up, Right, Down, PageUp, PageDown, Home, End, Insert,   // 356..364
    LeftShift = 368, RightShift, LeftControl, RightControl, LeftAlt, RightAlt,   // 368..373
};
constexpr int kFirstSpecialKey = 256;
constexpr int kKeyCount = 512;

/// The key of a printable character: its lower case ('A' -> 'a').
constexpr Key keyOf(char c) {
    return static_cast<Key>((c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : static_cast<unsigned char>(c));
}

/// A readable name: "a", "F1", "Left", "Escape".
const char* keyName(Key key);

struct Modifiers {
    bool shift = false;
    bool control = false;
    bool alt = false;
};

struct InputEvent {
    enum class Type {
        KeyDown,      // `key` went down (again while held: the keyboard's repeat)
        KeyUp,        // `key` came up
        Text,         // `character` was typed (Unicode code point; with Shift: 'A')
        MouseDown,    // `button` went down at `position`
        MouseUp,      // `button` came up at `position`
        MouseMove,    // the mouse is at `position` (buttons held or not)
        Wheel,        // `wheel` notches, + away from the user, at `position`
        Resize,       // the drawable area is `size` pixels now
    };
    Type type = Type::KeyDown;
    Key key = Key::Unknown;
    std::uint32_t character = 0;
    MouseButton button = MouseButton::Left;
    glm::vec2 position{0.0f};   // window pixels, origin top-left
    int wheel = 0;
    glm::ivec2 size{0};
    Modifiers modifiers;        // held when the event happened
};

/// "KeyDown F1 (shift)", "MouseDown Right at 10,20": for logs and tests.
const char* eventTypeName(InputEvent::Type type);

struct InputState {
    std::array<bool, 3> buttons{};          // indexed by MouseButton
    std::array<bool, kKeyCount> keys{};     // indexed by Key
    bool shift = false;
    bool control = false;
    bool alt = false;
    glm::vec2 mouse{0.0f};                  // window pixels, origin top-left

    bool button(MouseButton b) const { return buttons[static_cast<int>(b)]; }
    bool key(char c) const { return keys[static_cast<std::size_t>(keyOf(c))]; }
    bool key(Key k) const { return keys[static_cast<std::size_t>(k)]; }
    Modifiers modifiers() const { return {shift, control, alt}; }
};

} // namespace stoa
