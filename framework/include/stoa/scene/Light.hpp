#pragma once
// Light sources for Blinn-Phong shading (docs/labs/02_shading.md). Colours are
// linear RGB; intensity is folded into the colour.

#include <glm/vec3.hpp>

namespace stoa {

/// Light from infinitely far away, like the sun: same direction everywhere.
struct DirectionalLight {
    glm::vec3 direction{0.0f, -1.0f, 0.0f};   // world space, the way the light travels (need not be unit)
    glm::vec3 color{1.0f};
};

/// Light from a point, fading with distance d as 1 / (constant + linear d + quadratic d^2).
struct PointLight {
    glm::vec3 position{0.0f};                 // world space
    glm::vec3 color{1.0f};
    glm::vec3 attenuation{1.0f, 0.09f, 0.032f};   // (constant, linear, quadratic)
};

} // namespace stoa
