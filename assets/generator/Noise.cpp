#include "Noise.hpp"

#include <cmath>

namespace stoa::assets {

namespace {

// Quintic fade (6t^5 - 15t^4 + 10t^3): continuous first and second
// derivatives, so displaced surfaces and height maps show no lattice creases.
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

float lerp(float a, float b, float t) { return a + (b - a) * t; }

int wrap(int i, int period) {
    const int r = i % period;
    return r < 0 ? r + period : r;
}

} // namespace

// The "lowbias32" mixer: multiply-xorshift rounds with constants found by search
// for low bias; any good 32-bit mixer would do.
std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

float hashToUnit(int x, int y, int z, std::uint32_t seed) {
    std::uint32_t h = hash32(seed ^ 0x9e3779b9U);
    h = hash32(h ^ static_cast<std::uint32_t>(x));
    h = hash32(h ^ static_cast<std::uint32_t>(y));
    h = hash32(h ^ static_cast<std::uint32_t>(z));
    return static_cast<float>(h >> 8) / 16777216.0f;  // 24 bits: exact in a float
}

float tiledNoise(float x, float y, int period, std::uint32_t seed) {
    const float fx = std::floor(x), fy = std::floor(y);
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    const float tx = fade(x - fx), ty = fade(y - fy);
    auto at = [&](int i, int j) { return hashToUnit(wrap(i, period), wrap(j, period), 0, seed); };
    return lerp(lerp(at(x0, y0), at(x0 + 1, y0), tx), lerp(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx), ty);
}

float tiledFbm(float x, float y, int period, int octaves, std::uint32_t seed) {
    float sum = 0.0f, weight = 1.0f, total = 0.0f;
    for (int octave = 0; octave < octaves; ++octave) {
        sum += weight * tiledNoise(x, y, period, seed + static_cast<std::uint32_t>(octave) * 101U);
        total += weight;
        x *= 2.0f;
        y *= 2.0f;
        period *= 2;
        weight *= 0.5f;
    }
    return sum / total;
}

float noise3(float x, float y, float z, std::uint32_t seed) {
    const float fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy), z0 = static_cast<int>(fz);
    const float tx = fade(x - fx), ty = fade(y - fy), tz = fade(z - fz);
    auto at = [&](int i, int j, int k) { return hashToUnit(i, j, k, seed); };
    auto layer = [&](int k) {
        return lerp(lerp(at(x0, y0, k), at(x0 + 1, y0, k), tx), lerp(at(x0, y0 + 1, k), at(x0 + 1, y0 + 1, k), tx), ty);
    };
    return lerp(layer(z0), layer(z0 + 1), tz);
}

float fbm3(float x, float y, float z, int octaves, std::uint32_t seed) {
    float sum = 0.0f, weight = 1.0f, total = 0.0f;
    for (int octave = 0; octave < octaves; ++octave) {
        sum += weight * noise3(x, y, z, seed + static_cast<std::uint32_t>(octave) * 101U);
        total += weight;
        x *= 2.0f;
        y *= 2.0f;
        z *= 2.0f;
        weight *= 0.5f;
    }
    return sum / total;
}

} // namespace stoa::assets
