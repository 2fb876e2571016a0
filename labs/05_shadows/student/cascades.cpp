// Lab 05, going further: cascaded shadow maps for a large scene.
// Read docs/labs/05_shadows.md, "Cascaded shadow maps". The renderer
// (framework/src/render/ShadowRenderer.cpp) calls, every frame: cascadeSplits() once, then for each
// slice frustumSliceCorners() and cascadeLightMatrix(), and renders one map per
// slice with your renderShadowPass(). Only the cascade cases call these.

#include "lab01.hpp"

#include <stoa/core/NotImplemented.hpp>
#include "lab05.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace stoa {

std::vector<float> cascadeSplits(float near, float far, int count, float lambda) {
    // TODO(lab05): count + 1 distances, the i-th a lambda blend of the logarithmic
    // split near * (far / near)^(i / count) and the uniform one
    // near + (far - near) * i / count; the first exactly near, the last exactly far
    // (docs: "The split scheme").
    (void)near;
    (void)far;
    (void)count;
    (void)lambda;
    throw NotImplemented("cascadeSplits()");
}

std::array<glm::vec3, 8> frustumSliceCorners(const glm::mat4& viewMatrix, float fovYDegrees, float aspect,
                                             float sliceNear, float sliceFar) {
    // TODO(lab05): the eight corners (+-1, +-1, +-1) of the NDC cube taken back
    // to world space through the inverse of the slice's own projection
    // (perspectiveMatrix() with sliceNear, sliceFar) times viewMatrix; divide by w.
    // Corner k: x = +1 when k & 1, y = +1 when k & 2, z = +1 when k & 4
    // (docs: "Fitting each cascade").
    (void)viewMatrix;
    (void)fovYDegrees;
    (void)aspect;
    (void)sliceNear;
    (void)sliceFar;
    throw NotImplemented("frustumSliceCorners()");
}

glm::mat4 cascadeLightMatrix(const glm::vec3& lightDirection, const std::array<glm::vec3, 8>& sliceCornersWorld,
                             int mapSize, const glm::vec3& sceneMin, const glm::vec3& sceneMax) {
    // TODO(lab05): the corners' bounding sphere (centre, radius); a light view
    // that only rotates (lookAtMatrix() from the origin along lightDirection);
    // glm::ortho with a square side of 2 * radius around the centre, its
    // lower-left corner rounded down to whole texels (2 * radius / mapSize), and
    // a depth range from the sphere's far side to the scene box's corner nearest
    // the light (docs: "Fitting each cascade", "Texel snapping").
    (void)lightDirection;
    (void)sliceCornersWorld;
    (void)mapSize;
    (void)sceneMin;
    (void)sceneMax;
    throw NotImplemented("cascadeLightMatrix()");
}

} // namespace stoa
