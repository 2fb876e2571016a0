#pragma once
// The crowd step's arithmetic (CrowdSimulation, its agent step and its
// parallel step): headings, random numbers and grid cells computed from + and
// * only, so that every machine and every thread computes the same bits.
// Private to framework/src/crowd.

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace stoa::crowdmath {

constexpr float kPi = 3.14159265358979f;

inline std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// Sine, cosine and atan2 from + and * only, so that every machine computes the
// same bits (libm picks its implementation by CPU at run time, and a heading
// that differs in its last bit sends an agent elsewhere a thousand steps later).
// Accurate to about 1e-6, which is all a heading needs.
inline float wrapAngle(float angle) {
    // floor() by a cast (the headings stay far inside int's range): without
    // SSE4.1 std::floor is a call into libm, and this runs several times per agent.
    const float t = angle * (0.5f / kPi) + 0.5f;
    float turns = static_cast<float>(static_cast<int>(t));
    if (turns > t) turns -= 1.0f;
    return angle - turns * (2.0f * kPi);   // [-pi, pi)
}

inline float portableSin(float x) {
    x = wrapAngle(x);
    // sin(pi - x) = sin(x) folds [-pi, pi) onto [-pi/2, pi/2].
    if (x > 0.5f * kPi) x = kPi - x;
    else if (x < -0.5f * kPi) x = -kPi - x;
    const float x2 = x * x;
    return x * (1.0f + x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f)))));
}

inline float portableCos(float x) { return portableSin(x + 0.5f * kPi); }

inline float portableAtan2(float y, float x) {
    const float ax = std::fabs(x), ay = std::fabs(y);
    if (ax == 0.0f && ay == 0.0f) return 0.0f;
    // atan on [0, 1] from a polynomial in t = min / max, then the octant.
    const float t = std::min(ax, ay) / std::max(ax, ay);
    const float t2 = t * t;
    float a = t * (0.99997726f + t2 * (-0.33262347f + t2 * (0.19354346f + t2 * (-0.11643287f + t2 * (0.05265332f - t2 * 0.01172120f)))));
    if (ay > ax) a = 0.5f * kPi - a;
    if (x < 0.0f) a = kPi - a;
    return y < 0.0f ? -a : a;
}

/// (sin, cos) of a heading: 0 faces +z, pi/2 faces +x.
inline glm::vec2 direction(float heading) { return {portableSin(heading), portableCos(heading)}; }

/// The grid cell that holds coordinate `cells` (in cell units), clamped to
/// [0, count - 1]: the same as clamp(floor(cells)), without a call into libm
/// (std::floor is one without SSE4.1, and this runs several times per agent).
inline int cellIndex(float cells, int count) {
    return static_cast<int>(std::clamp(cells, 0.0f, static_cast<float>(count - 1)));
}

inline float distanceSquared(glm::vec2 a, glm::vec2 b) {
    const glm::vec2 d = a - b;
    return glm::dot(d, d);
}

} // namespace stoa::crowdmath
