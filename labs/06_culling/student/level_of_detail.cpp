// Lab 06, part 3: how much detail an object needs, from its size on the screen.
// Read docs/labs/06_culling.md, "Level of detail". The framework made each
// mesh's levels with meshoptimizer (stoa/geometry/LevelOfDetail.hpp); you decide
// which one to draw, or none.

#include "lab06.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

float lodQuality(const BoundingSphere& sphere, const glm::vec3& eye, float fovYDegrees, int viewportHeight,
                 const LodSettings& settings) {
    // TODO(lab06): 1 when the eye is inside the sphere. Otherwise the radius on
    // screen in pixels, rho = (viewportHeight / 2) * r / (distance * tan(fovY / 2))
    // (fovY in radians: glm::radians), mapped to [0, 1] linearly:
    // (rho - hiddenBelowPixels) / (fullDetailPixels - hiddenBelowPixels), clamped
    // (docs: "Level of detail").
    (void)sphere;
    (void)eye;
    (void)fovYDegrees;
    (void)viewportHeight;
    (void)settings;
    throw NotImplemented("lodQuality()");
}

int levelOfDetail(float quality, int levelCount) {
    // TODO(lab06): -1 for quality <= 0 (not drawn); otherwise
    // floor((1 - quality) * levelCount), but never more than levelCount - 1
    // (docs: "Level of detail").
    (void)quality;
    (void)levelCount;
    throw NotImplemented("levelOfDetail()");
}

} // namespace stoa
