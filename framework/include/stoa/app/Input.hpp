#pragma once
// What the user is holding right now, as the window last reported it.

#include <array>

#include <glm/vec2.hpp>

namespace stoa {

enum class MouseButton { Left = 0, Middle = 1, Right = 2 };

struct InputState {
    std::array<bool, 3> buttons{};     // indexed by MouseButton
    std::array<bool, 256> keys{};      // ASCII, lower case for letters
    bool shift = false;
    bool control = false;
    bool alt = false;
    glm::vec2 mouse{0.0f};             // window pixels, origin top-left

    bool button(MouseButton b) const { return buttons[static_cast<int>(b)]; }
    bool key(char c) const { return keys[static_cast<unsigned char>(c)]; }
};

} // namespace stoa
