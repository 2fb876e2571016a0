// Lab 06, part 3: how much detail an object needs, from its size on the screen.
// Read docs/labs/06_culling.md, "Level of detail". The framework made each
// mesh's levels with meshoptimizer (stoa/geometry/LevelOfDetail.hpp); you decide
// which one to draw, or none.

#include "lab06.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

float lodQuality(const BoundingSphere& sphere, const glm::vec3& eye, float fovYDegrees, int viewportHeight,
                 const LodSettings& settings) {
    const float distance = glm::length(sphere.center - eye);
    if (distance <= sphere.radius) return 1.0f;
    const float pixels = 0.5f * static_cast<float>(viewportHeight) * sphere.radius /
                         (distance * std::tan(0.5f * glm::radians(fovYDegrees)));
    const float quality = (pixels - settings.hiddenBelowPixels) / (settings.fullDetailPixels - settings.hiddenBelowPixels);
    return std::clamp(quality, 0.0f, 1.0f);
}

int levelOfDetail(float quality, int levelCount) {
    if (!(quality > 0.0f)) return -1;
    const int level = static_cast<int>(std::floor((1.0f - quality) * static_cast<float>(levelCount)));
    return std::min(level, levelCount - 1);
}

} // namespace stoa
