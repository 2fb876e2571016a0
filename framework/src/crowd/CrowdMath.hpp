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

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

/// The per-agent part of an agent's random numbers (CrowdSimulation::randomBase()).
inline std::uint32_t agentHash(std::uint32_t seed, std::uint32_t agent) { return hash32(seed * 0x9E3779B9u + agent); }

/// The base of an agent's random numbers at a step.
inline std::uint32_t stepHash(std::uint32_t agentHash, long long step) {
    return hash32(agentHash ^ static_cast<std::uint32_t>(step) * 0x85EBCA6Bu);
}

/// A salt as randomUnit() mixes it into the base (a salt's part, computed once where the salt is known).
inline std::uint32_t mixedSalt(std::uint32_t salt) { return salt * 0xC2B2AE35u; }

/// randomUnit() of a salt already mixed (mixedSalt()).
inline float randomMixed(std::uint32_t base, std::uint32_t mixed) {
    const std::uint32_t x = hash32(base ^ mixed);
    return static_cast<float>(x >> 8u) * (1.0f / 16777216.0f);
}

/// A number in [0, 1) for (base, salt).
inline float randomUnit(std::uint32_t base, std::uint32_t salt) { return randomMixed(base, mixedSalt(salt)); }

/// randomMixed(base, mixedSalts[i]) for four salts at once. With SSE2 the
/// four side by side: the same integer operations lane by lane (a 32-bit
/// product is the low half of the 64-bit one), so the same numbers.
inline void randomUnits(std::uint32_t base, const std::uint32_t mixedSalts[4], float units[4]) {
#if defined(__SSE2__)
    const auto times = [](__m128i x, std::uint32_t factor) {
        const __m128i f = _mm_set1_epi32(static_cast<int>(factor));
        const __m128i even = _mm_mul_epu32(x, f);                      // lanes 0 and 2, 64 bits each
        const __m128i odd = _mm_mul_epu32(_mm_srli_epi64(x, 32), f);   // lanes 1 and 3
        return _mm_unpacklo_epi32(_mm_shuffle_epi32(even, _MM_SHUFFLE(0, 0, 2, 0)),
                                  _mm_shuffle_epi32(odd, _MM_SHUFFLE(0, 0, 2, 0)));
    };
    __m128i x = _mm_xor_si128(_mm_set1_epi32(static_cast<int>(base)),
                              _mm_loadu_si128(reinterpret_cast<const __m128i*>(mixedSalts)));
    // hash32()
    x = _mm_xor_si128(x, _mm_srli_epi32(x, 16));
    x = times(x, 0x7feb352du);
    x = _mm_xor_si128(x, _mm_srli_epi32(x, 15));
    x = times(x, 0x846ca68bu);
    x = _mm_xor_si128(x, _mm_srli_epi32(x, 16));
    // 24 bits, converted exactly, times 2^-24 exactly.
    _mm_storeu_ps(units, _mm_mul_ps(_mm_cvtepi32_ps(_mm_srli_epi32(x, 8)), _mm_set1_ps(1.0f / 16777216.0f)));
#else
    for (int i = 0; i < 4; ++i) units[i] = randomMixed(base, mixedSalts[i]);
#endif
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

/// (sin, cos) of a heading: 0 faces +z, pi/2 faces +x. With SSE2 (every
/// x86-64) the sine and the cosine side by side in one register: the same
/// operations in the same order as portableSin() and portableCos(), each
/// rounded alike lane by lane, so the same bits for half the instructions.
inline glm::vec2 direction(float heading) {
#if defined(__SSE2__)
    const __m128 angle = _mm_setr_ps(heading, heading + 0.5f * kPi, 0.0f, 0.0f);
    // wrapAngle()
    const __m128 t = _mm_add_ps(_mm_mul_ps(angle, _mm_set1_ps(0.5f / kPi)), _mm_set1_ps(0.5f));
    __m128 turns = _mm_cvtepi32_ps(_mm_cvttps_epi32(t));
    turns = _mm_sub_ps(turns, _mm_and_ps(_mm_cmpgt_ps(turns, t), _mm_set1_ps(1.0f)));
    __m128 x = _mm_sub_ps(angle, _mm_mul_ps(turns, _mm_set1_ps(2.0f * kPi)));
    // The fold onto [-pi/2, pi/2] ...
    const __m128 above = _mm_cmpgt_ps(x, _mm_set1_ps(0.5f * kPi));
    const __m128 below = _mm_cmplt_ps(x, _mm_set1_ps(-0.5f * kPi));
    const __m128 folded = _mm_or_ps(_mm_and_ps(above, _mm_sub_ps(_mm_set1_ps(kPi), x)),
                                    _mm_and_ps(below, _mm_sub_ps(_mm_set1_ps(-kPi), x)));
    x = _mm_or_ps(folded, _mm_andnot_ps(_mm_or_ps(above, below), x));
    // ... and the polynomial, innermost first.
    const __m128 x2 = _mm_mul_ps(x, x);
    __m128 p = _mm_add_ps(_mm_set1_ps(-1.0f / 5040.0f), _mm_mul_ps(x2, _mm_set1_ps(1.0f / 362880.0f)));
    p = _mm_add_ps(_mm_set1_ps(1.0f / 120.0f), _mm_mul_ps(x2, p));
    p = _mm_add_ps(_mm_set1_ps(-1.0f / 6.0f), _mm_mul_ps(x2, p));
    p = _mm_add_ps(_mm_set1_ps(1.0f), _mm_mul_ps(x2, p));
    float lanes[4];
    _mm_storeu_ps(lanes, _mm_mul_ps(x, p));
    return {lanes[0], lanes[1]};
#else
    return {portableSin(heading), portableCos(heading)};
#endif
}

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
