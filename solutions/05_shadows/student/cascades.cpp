// Lab 05, going further: cascaded shadow maps for a large scene.
// Read docs/labs/05_shadows.md, "Cascaded shadow maps". The renderer
// (framework/src/render/ShadowRenderer.cpp) calls, every frame: cascadeSplits() once, then for each
// slice frustumSliceCorners() and cascadeLightMatrix(), and renders one map per
// slice with your renderShadowPass().

#include "lab01.hpp"

#include <stoa/core/Assert.hpp>
#include "lab05.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace stoa {

namespace {

// An up vector not parallel to `direction` (a sun straight overhead has no "up").
glm::vec3 upFor(const glm::vec3& direction) {
    return std::abs(glm::normalize(direction).y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

} // namespace

std::vector<float> cascadeSplits(float near, float far, int count, float lambda) {
    STOA_ASSERT(near > 0.0f && far > near && count >= 1,
                "cascadeSplits(): needs 0 < near < far and at least one cascade");
    std::vector<float> splits(static_cast<std::size_t>(count) + 1);
    for (int i = 0; i <= count; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(count);
        const float uniform = near + (far - near) * t;
        const float logarithmic = near * std::pow(far / near, t);
        splits[static_cast<std::size_t>(i)] = lambda * logarithmic + (1.0f - lambda) * uniform;
    }
    // Exact ends: pow() may miss `far` by an ulp.
    splits.front() = near;
    splits.back() = far;
    return splits;
}

std::array<glm::vec3, 8> frustumSliceCorners(const glm::mat4& viewMatrix, float fovYDegrees, float aspect,
                                             float sliceNear, float sliceFar) {
    // The NDC cube's corners, taken back through the slice's own projection.
    const glm::mat4 sliceProjection = perspectiveMatrix(fovYDegrees, aspect, sliceNear, sliceFar);
    const glm::mat4 clipToWorld = glm::inverse(sliceProjection * viewMatrix);
    std::array<glm::vec3, 8> corners;
    for (int k = 0; k < 8; ++k) {
        const glm::vec4 ndc((k & 1) ? 1.0f : -1.0f, (k & 2) ? 1.0f : -1.0f, (k & 4) ? 1.0f : -1.0f, 1.0f);
        const glm::vec4 world = clipToWorld * ndc;
        corners[static_cast<std::size_t>(k)] = glm::vec3(world) / world.w;
    }
    return corners;
}

glm::mat4 cascadeLightMatrix(const glm::vec3& lightDirection, const std::array<glm::vec3, 8>& sliceCornersWorld,
                             int mapSize, const glm::vec3& sceneMin, const glm::vec3& sceneMax) {
    // The slice's bounding sphere: its radius depends on the split distances only,
    // not on where the camera looks, so the texel size stays put.
    glm::vec3 center(0.0f);
    for (const glm::vec3& corner : sliceCornersWorld) center += corner / 8.0f;
    float radius = 0.0f;
    for (const glm::vec3& corner : sliceCornersWorld) radius = std::max(radius, glm::length(corner - center));
    // Rounded up to 1/16 m, so that float noise in the corners cannot change it either.
    radius = std::ceil(radius * 16.0f) / 16.0f;

    // A light view that is a rotation only (eye at the origin): moving the
    // camera then moves the box's origin in light space and nothing else.
    const glm::mat4 view = lookAtMatrix(glm::vec3(0.0f), glm::normalize(lightDirection), upFor(lightDirection));
    const glm::vec3 centerLight = glm::vec3(view * glm::vec4(center, 1.0f));

    // Snap the box's lower-left corner to whole texels (docs: "Texel snapping").
    const float texel = 2.0f * radius / static_cast<float>(mapSize);
    const float left = std::floor((centerLight.x - radius) / texel) * texel;
    const float bottom = std::floor((centerLight.y - radius) / texel) * texel;

    // Depth: the sphere, stretched towards the light (larger z: the view looks
    // down -Z) to the scene's nearest corner, where occluders may stand.
    float zHigh = centerLight.z + radius;
    const float zLow = centerLight.z - radius;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 world((corner & 1) ? sceneMax.x : sceneMin.x, (corner & 2) ? sceneMax.y : sceneMin.y,
                              (corner & 4) ? sceneMax.z : sceneMin.z);
        zHigh = std::max(zHigh, (view * glm::vec4(world, 1.0f)).z);
    }
    const float margin = 0.01f * (zHigh - zLow);
    const float side = 2.0f * radius;
    return glm::ortho(left, left + side, bottom, bottom + side, -zHigh - margin, -zLow + margin) * view;
}

} // namespace stoa
