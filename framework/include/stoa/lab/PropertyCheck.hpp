#pragma once
// A property check: a graded case that tests what a picture cannot show (the
// shadow map moving by whole texels as the camera moves, a normal map that
// wraps at its borders). A check calls the student's functions on inputs of its
// own and tests a property the docs state (for example: shifting the height map
// by k texels shifts its normal map by k texels); it holds no answer to copy.
//
// In a lab's cases.ini a check is a case with a `check` key and no picture:
//
//   [case texel_snapping]
//   description = The cascade's box moves by whole texels when the camera moves by less
//   check = texel_snapping
//   points = 1
//
// `labNN --check NAME` (or `--check all`) runs it and prints the verdict; the
// grader runs it as `--render NAME` and reads the exit status: 0 it holds,
// kExitCheckFailed (4) it does not, 3 a stub is still in place.

#include <glm/vec3.hpp>

#include <cstdint>
#include <cstdio>
#include <string>

namespace stoa {

/// What a check found: whether the property holds, and one line that says what
/// was measured (and, when it fails, what the docs require instead).
struct CheckResult {
    bool holds = false;
    std::string message;

    static CheckResult pass(std::string message) { return {true, std::move(message)}; }
    static CheckResult fail(std::string message) { return {false, std::move(message)}; }
};

/// A check's own inputs, from a fixed seed: the same numbers on every run and
/// every machine (a linear congruential generator; not std::mt19937's
/// distributions, whose results the C++ standard leaves to each library).
class CheckRandom {
public:
    explicit CheckRandom(std::uint32_t seed) : m_state(seed) {}
    /// A number in [0, 1), 24 bits.
    float next() { return static_cast<float>(step() >> 8) / 16777216.0f; }
    /// A number in [low, high).
    float between(float low, float high) { return low + (high - low) * next(); }
    /// A byte, 0 to 255.
    std::uint8_t nextByte() { return static_cast<std::uint8_t>(step() >> 24); }

private:
    std::uint32_t step() { return m_state = m_state * 1664525u + 1013904223u; }
    std::uint32_t m_state;
};

/// A number for a check's message, with `decimals` digits after the point: "2.39".
inline std::string checkNumber(double value, int decimals = 2) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

/// A vector for a check's message: "(0.000, 1.000, 0.000)".
inline std::string checkVector(const glm::vec3& v, int decimals = 3) {
    return "(" + checkNumber(v.x, decimals) + ", " + checkNumber(v.y, decimals) + ", " + checkNumber(v.z, decimals) + ")";
}

} // namespace stoa
