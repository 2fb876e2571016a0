// Lab 10, part 3: animating MD2 characters between their key frames. Read
// docs/labs/10_crowds.md, "Key-frame animation", first.

#include "lab10.hpp"

#include <stoa/crowd/CrowdLab.hpp>

#include <glm/geometric.hpp>

#include <cmath>

namespace stoa {

Md2FramePair md2FramesAt(const Md2Animation& animation, float seconds, float framesPerSecond) {
    // Frames since the start, wrapped into one loop of the animation.
    const float frames = seconds * framesPerSecond;
    float looped = frames - std::floor(frames / animation.count) * animation.count;
    if (looped >= animation.count) looped = 0.0f;   // rounded up to a whole loop: the next one starts
    const int k = static_cast<int>(std::floor(looped));
    Md2FramePair pair;
    pair.first = animation.first + k;
    pair.second = animation.first + (k + 1) % animation.count;   // the last frame blends into the first
    pair.t = looped - static_cast<float>(k);
    return pair;
}

void blendMd2Frames(const Md2Frame& first, const Md2Frame& second, float t, std::vector<glm::vec3>& positions,
                    std::vector<glm::vec3>& normals) {
    const std::size_t count = first.positions.size();
    positions.resize(count);
    normals.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        positions[i] = first.positions[i] + (second.positions[i] - first.positions[i]) * t;
        // Two unit normals blended are shorter than one: normalize again.
        const glm::vec3 n = first.normals[i] + (second.normals[i] - first.normals[i]) * t;
        const float length = glm::length(n);
        normals[i] = length > 0.0f ? n / length : first.normals[i];
    }
}

} // namespace stoa
