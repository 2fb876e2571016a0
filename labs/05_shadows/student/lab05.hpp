#pragma once
// Lab 05: everything you write (light_space.cpp, shadow_pass.cpp and, for cascaded shadow maps,
// cascades.cpp). docs/labs/05_shadows.md derives each function. The lab's app, the tests and later
// labs include this header; your files define what it declares.
//
// Conventions as in lab 01's matrices: right-handed world, column vectors, OpenGL clip space
// ([-1, 1]^3 after the divide by w).
//
// The framework's ShadowRenderer calls renderShadowPass() and the cascade functions through its
// student-code table (hand_over.cpp hands them over).

#include "lab01.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace stoa {

class Framebuffer;
class Program;
class Scene;

/// World -> light clip space for a directional light (the sun): an orthographic
/// projection looking along `direction` (world space, the way the light travels,
/// need not be unit) whose box is fitted to the light-space extent of the eight
/// corners of the world-space box [sceneMin, sceneMax]. Every point of that box
/// lands inside [-1, 1]^3, and the box touches the x and y sides.
glm::mat4 directionalLightMatrix(const glm::vec3& direction, const glm::vec3& sceneMin, const glm::vec3& sceneMax);

/// World -> light clip space for a point light that shines from `position`
/// towards `target` (world space): a perspective projection with a square
/// field of view of `fovYDegrees` and depth range [near, far] (world units, 0 < near < far).
glm::mat4 spotLightMatrix(const glm::vec3& position, const glm::vec3& target, float fovYDegrees, float near,
                          float far);

/// The first pass: draws every object of `scene` into the depth texture of
/// `shadowMap` (a Framebuffer with FramebufferOptions::depthTexture), seen through
/// `lightSpaceMatrix`. `depthProgram` is shaders/shadows/depth.vert + depth.frag:
/// it reads uLightSpaceMatrix and uModel. Leaves `shadowMap` bound; the caller
/// binds its own target again.
void renderShadowPass(const Scene& scene, const Framebuffer& shadowMap, const Program& depthProgram,
                      const glm::mat4& lightSpaceMatrix);

/// Cascaded shadow maps, the split scheme: `count` + 1 view depths (world
/// units, distances in front of the camera) that cut [near, far] into `count`
/// slices; the first is `near`, the last `far`, and they increase. `lambda` in
/// [0, 1] blends the logarithmic split (1) with the uniform one (0): the
/// "practical split" (docs: "The split scheme"). 0 < near < far, count >= 1.
std::vector<float> cascadeSplits(float near, float far, int count, float lambda);

/// The eight world-space corners of the slice of a camera's view frustum between
/// the view depths `sliceNear` and `sliceFar` (world units, 0 < sliceNear < sliceFar):
/// `viewMatrix` is the camera's world -> view, `fovYDegrees` and `aspect`
/// (width / height) its projection's. Corner k has x on the right side when
/// k & 1, y on top when k & 2, and lies on the far plane when k & 4.
std::array<glm::vec3, 8> frustumSliceCorners(const glm::mat4& viewMatrix, float fovYDegrees, float aspect,
                                             float sliceNear, float sliceFar);

/// World -> light clip space for one cascade of a directional light: an
/// orthographic projection looking along `lightDirection` (world space, need
/// not be unit) whose square side is the diameter of the bounding sphere of
/// `sliceCornersWorld`, so that it does not change as the camera turns, and
/// whose origin is snapped to whole texels of a `mapSize`-texel map, so that
/// the map slides over the world in texel steps as the camera moves. The depth
/// range covers the sphere and reaches towards the light to the world-space box
/// [sceneMin, sceneMax], so that occluders outside the slice still cast into it.
glm::mat4 cascadeLightMatrix(const glm::vec3& lightDirection, const std::array<glm::vec3, 8>& sliceCornersWorld,
                             int mapSize, const glm::vec3& sceneMin, const glm::vec3& sceneMax);

} // namespace stoa
