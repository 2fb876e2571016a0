#pragma once
// Seeded random numbers for tests that compare with independent references on
// many random inputs: the same on every machine (std::uniform_real_distribution
// differs between standard libraries, so floats come from our own mapping of
// std::mt19937's output: 24 bits into [low, high)).

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <random>

namespace stoa::test {

class Random {
public:
    explicit Random(std::uint32_t seed) : m_engine(seed) {}
    float uniform(float low, float high) {
        return low + (high - low) * static_cast<float>(m_engine() >> 8) * (1.0f / 16777216.0f);
    }
    /// 0 .. n - 1 (n > 0).
    int below(int n) { return static_cast<int>(m_engine() % static_cast<std::uint32_t>(n)); }
    bool chance(float p) { return uniform(0.0f, 1.0f) < p; }
    glm::vec3 inBox(const glm::vec3& low, const glm::vec3& high) {
        return {uniform(low.x, high.x), uniform(low.y, high.y), uniform(low.z, high.z)};
    }
    /// A direction, uniform on the sphere (rejection from the cube).
    glm::vec3 unitVector() {
        for (;;) {
            const glm::vec3 v = inBox(glm::vec3(-1.0f), glm::vec3(1.0f));
            const float length = glm::length(v);
            if (length > 0.1f && length <= 1.0f) return v / length;
        }
    }

private:
    std::mt19937 m_engine;
};

} // namespace stoa::test
