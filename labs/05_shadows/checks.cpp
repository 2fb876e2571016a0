// Lab 05's property checks; see checks.hpp. The slices here are shapes of the
// checks' own (eight points), not computed frusta: only the function under test
// is yours in each check.

#include "checks.hpp"

#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/StudentPass.hpp>
#include "lab05.hpp"
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace lab05 {

namespace {

std::string number(double value, int decimals = 2) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// Whether a point lies in [-1, 1]^3 (a little slack for rounding); false for NaN,
// which a degenerate box (near = far) makes.
bool insideClipCube(const glm::vec3& ndc) {
    return std::abs(ndc.x) <= 1.0001f && std::abs(ndc.y) <= 1.0001f && std::abs(ndc.z) <= 1.0001f;
}

// A slice-like shape: a small quad near the camera at the origin, a large one
// further along -Z, the order of frustumSliceCorners() (x right when k & 1, y up
// when k & 2, far when k & 4).
std::array<glm::vec3, 8> sliceShape() {
    std::array<glm::vec3, 8> corners;
    for (int k = 0; k < 8; ++k) {
        const bool far = (k & 4) != 0;
        const float halfWidth = far ? 9.0f : 2.5f, halfHeight = far ? 5.5f : 1.5f, depth = far ? 16.0f : 4.0f;
        corners[static_cast<std::size_t>(k)] =
            glm::vec3((k & 1) ? halfWidth : -halfWidth, (k & 2) ? halfHeight : -halfHeight, -depth);
    }
    return corners;
}

std::array<glm::vec3, 8> transformed(const std::array<glm::vec3, 8>& corners, const glm::mat4& matrix) {
    std::array<glm::vec3, 8> result;
    for (std::size_t k = 0; k < 8; ++k) result[k] = glm::vec3(matrix * glm::vec4(corners[k], 1.0f));
    return result;
}

// Whether the depth map holds something nearer than the far plane at its centre.
bool depthWritten(const stoa::Framebuffer& map) {
    const std::vector<float> depth = map.readDepth();
    const int center = (map.height() / 2) * map.width() + map.width() / 2;
    return depth[static_cast<std::size_t>(center)] < 0.999f;
}

} // namespace

stoa::CheckResult checkDepthPassBothFaces(const stoa::Program& depthProgram) {
    stoa::FramebufferOptions options;
    options.color = false;
    options.depthTexture = true;
    const stoa::Framebuffer map(64, 64, options);
    // A light below the square, looking up at it: the square's front face (+Y) looks away from it.
    const glm::mat4 fromBelow = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 10.0f) *
                                glm::lookAt(glm::vec3(0.0f, -5.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::mat4 fromAbove = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 10.0f) *
                                glm::lookAt(glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    stoa::Scene scene;
    scene.add(std::make_unique<stoa::MeshObject>(std::make_shared<const stoa::GpuMesh>(stoa::shapes::plane(2.0f, 1))));

    // Through runStudentPass(): GL state set behind RenderState is named, not
    // mistaken for a pass that culls or draws nothing.
    stoa::runStudentPass("renderShadowPass", [&] { stoa::renderShadowPass(scene, map, depthProgram, fromAbove); });
    const bool front = depthWritten(map);
    stoa::runStudentPass("renderShadowPass", [&] { stoa::renderShadowPass(scene, map, depthProgram, fromBelow); });
    const bool back = depthWritten(map);
    stoa::Framebuffer::bindDefault();
    if (front && back) return stoa::CheckResult::pass("a square leaves its depth in the map with either face towards the light");
    if (front)
        return stoa::CheckResult::fail("a square whose back faces the light left no depth in the map, with its front "
                                       "towards the light it did: the depth pass culls faces, but single-sided "
                                       "surfaces cast shadows from both sides (docs: The two passes)");
    if (back)
        return stoa::CheckResult::fail("a square whose front faces the light left no depth in the map, with its back "
                                       "towards the light it did: the depth pass culls the faces that face the light "
                                       "(docs: The two passes)");
    return stoa::CheckResult::fail("a square in the middle of the light's view left no depth in the map with either "
                                   "face towards the light: clear the map, enable the depth test and draw every "
                                   "object with the depth program (docs: The two passes)");
}

stoa::CheckResult checkSplitsBlendTheSchemes() {
    struct Split {
        float near, far;
        int count;
        float lambda;
    };
    // Near and far of the same order, where the uniform split's `near` matters,
    // and the cases' own range; lambda from uniform (0) to logarithmic (1).
    // The last two blend to ends an ulp off near (lambda 0.1) and far (0.3 to 60)
    // in float arithmetic, unless they are written exactly.
    const Split splits[] = {{2.0f, 10.0f, 4, 0.0f}, {2.0f, 10.0f, 4, 0.3f}, {2.0f, 10.0f, 4, 1.0f},
                            {0.5f, 60.0f, 3, 0.75f}, {0.1f, 110.0f, 4, 0.75f}, {0.1f, 60.0f, 4, 0.1f},
                            {0.3f, 60.0f, 3, 0.75f}};
    for (const Split& split : splits) {
        const std::vector<float> got = stoa::cascadeSplits(split.near, split.far, split.count, split.lambda);
        const std::string what = "cascadeSplits(" + number(split.near, 1) + ", " + number(split.far, 1) + ", " +
                                 std::to_string(split.count) + ", " + number(split.lambda) + ")";
        if (got.size() != static_cast<std::size_t>(split.count) + 1)
            return stoa::CheckResult::fail(what + " gave " + std::to_string(got.size()) + " depths; expected count + 1 = " +
                                           std::to_string(split.count + 1) + " (docs: The split scheme)");
        for (int i = 0; i <= split.count; ++i) {
            const double t = static_cast<double>(i) / split.count;
            const double uniform = split.near + (split.far - split.near) * t;
            const double logarithmic = split.near * std::pow(static_cast<double>(split.far) / split.near, t);
            const double expected = split.lambda * logarithmic + (1.0 - split.lambda) * uniform;
            const float value = got[static_cast<std::size_t>(i)];
            if (std::isfinite(value) && std::abs(value - expected) <= 1e-4 * expected) continue;
            return stoa::CheckResult::fail(
                what + " gave " + number(value, 4) + " m for depth " + std::to_string(i) + "; lambda z_log + (1 - "
                "lambda) z_uniform there is " + number(expected, 4) + " m, with z_uniform = near + (far - near) i / N = " +
                number(uniform, 4) + " and z_log = near (far / near)^(i / N) = " + number(logarithmic, 4) +
                " (docs: The split scheme)");
        }
        if (got.front() != split.near || got.back() != split.far)
            return stoa::CheckResult::fail(what + " starts at " + number(got.front(), 6) + " and ends at " +
                                           number(got.back(), 6) + "; the first depth is exactly near and the last "
                                           "exactly far (docs: The split scheme)");
    }
    return stoa::CheckResult::pass("the splits blend the logarithmic and uniform schemes by lambda (0 to 1) for seven "
                                   "ranges, from exactly near to exactly far");
}

stoa::CheckResult checkSliceCorners() {
    const float fov = 50.0f, aspect = 1.6f, sliceNear = 2.0f, sliceFar = 11.0f;
    const glm::mat4 view = glm::lookAt(glm::vec3(3.0f, 2.0f, 6.0f), glm::vec3(-1.0f, 0.5f, -2.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    const std::array<glm::vec3, 8> corners = stoa::frustumSliceCorners(view, fov, aspect, sliceNear, sliceFar);
    const float tangent = std::tan(glm::radians(fov) * 0.5f);
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 inView = glm::vec3(view * glm::vec4(corners[static_cast<std::size_t>(k)], 1.0f));
        const bool far = (k & 4) != 0;
        const float distance = far ? sliceFar : sliceNear;
        const std::string which = std::string("corner ") + std::to_string(k) + " (" + (far ? "far" : "near") + ", " +
                                  ((k & 1) ? "right" : "left") + ", " + ((k & 2) ? "top" : "bottom") + ")";
        if (std::abs(-inView.z - distance) > 1e-3f * distance) {
            std::string message = which + " lies " + number(-inView.z) + " m in front of the camera; the slice's " +
                                  (far ? "far" : "near") + " side is at " + number(distance) + " m";
            // Where NDC z = 0 lands: the middle of OpenGL's [-1, 1] depth range, not its near plane.
            const float ndcZeroDepth = 2.0f * sliceNear * sliceFar / (sliceNear + sliceFar);
            if (!far && std::abs(-inView.z - ndcZeroDepth) < 1e-2f * ndcZeroDepth)
                message += "; " + number(ndcZeroDepth) + " m is where NDC z = 0 lands, and OpenGL's NDC cube spans z "
                           "from -1 (near) to +1 (far)";
            return stoa::CheckResult::fail(message + " (docs: Fitting each cascade)");
        }
        const glm::vec2 expected(((k & 1) ? 1.0f : -1.0f) * tangent * aspect * distance,
                                 ((k & 2) ? 1.0f : -1.0f) * tangent * distance);
        if (glm::length(glm::vec2(inView) - expected) > 1e-3f * distance)
            return stoa::CheckResult::fail(which + " lies at (" + number(inView.x) + ", " + number(inView.y) +
                                           ") in view space; a corner of the field of view at that distance is at (" +
                                           number(expected.x) + ", " + number(expected.y) +
                                           ") (docs: Fitting each cascade)");
    }
    return stoa::CheckResult::pass("the eight corners lie on the slice's near and far sides, at the edges of the field of view");
}

stoa::CheckResult checkCascadeDepthReachesOccluders() {
    const glm::vec3 sceneMin(-40.0f, 0.0f, -40.0f), sceneMax(40.0f, 30.0f, 40.0f);
    // A slice near the ground, seen by a camera 1.7 m up; the scene's box rises far above it.
    const glm::mat4 camera = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.7f, 0.0f));
    // Suns from four sides, so that each upper corner of the scene's box is once the nearest to the light.
    for (const glm::vec3 light : {glm::vec3(0.3f, -1.0f, 0.2f), glm::vec3(-0.3f, -1.0f, -0.2f),
                                  glm::vec3(0.3f, -1.0f, -0.2f), glm::vec3(-0.3f, -1.0f, 0.2f)}) {
        const glm::mat4 matrix = stoa::cascadeLightMatrix(light, transformed(sliceShape(), camera), 1024, sceneMin, sceneMax);
        for (float x : {sceneMin.x, sceneMax.x})
            for (float y : {sceneMin.y, sceneMax.y})
                for (float z : {sceneMin.z, sceneMax.z}) {
                    const glm::vec4 clip = matrix * glm::vec4(x, y, z, 1.0f);
                    const float depth = clip.z / clip.w;
                    if (depth < -1.0001f)
                        return stoa::CheckResult::fail(
                            "with the light along (" + number(light.x, 1) + ", " + number(light.y, 1) + ", " +
                            number(light.z, 1) + "), the scene's corner (" + number(x, 0) + ", " + number(y, 0) + ", " +
                            number(z, 0) + ") lies nearer the light than the box's near side (NDC z " + number(depth) +
                            " < -1): an occluder there would cast no shadow into the slice; the depth range must "
                            "reach towards the light to every corner of the scene's bounds (docs: Fitting each cascade)");
                }
    }
    return stoa::CheckResult::pass("every corner of the scene's box lies behind the box's near side, as seen from the "
                                   "light, for suns from four sides");
}

stoa::CheckResult checkLightBoxHoldsTheScene() {
    const glm::vec3 sceneMin(-15.0f, -0.5f, -12.0f), sceneMax(15.0f, 7.3f, 18.0f);
    const glm::vec3 lights[] = {{0.45f, -1.0f, 0.3f}, {-0.6f, -0.8f, 0.1f}, {0.2f, -0.3f, -1.0f}, {0.0f, -1.0f, 0.0f}};
    for (const glm::vec3& light : lights) {
        const glm::mat4 matrix = stoa::directionalLightMatrix(light, sceneMin, sceneMax);
        std::vector<glm::vec3> corners;
        for (const float x : {sceneMin.x, sceneMax.x})
            for (const float y : {sceneMin.y, sceneMax.y})
                for (const float z : {sceneMin.z, sceneMax.z}) corners.emplace_back(x, y, z);
        for (const glm::vec3& world : corners) {
            const glm::vec4 clip = matrix * glm::vec4(world, 1.0f);
            const glm::vec3 ndc = glm::vec3(clip) / clip.w;
            if (!insideClipCube(ndc))
                return stoa::CheckResult::fail(
                    "directionalLightMatrix() with the light along (" + number(light.x) + ", " + number(light.y) + ", " +
                    number(light.z) + ") puts the scene's corner (" + number(world.x, 1) + ", " + number(world.y, 1) +
                    ", " + number(world.z, 1) + ") at (" + number(ndc.x, 3) + ", " + number(ndc.y, 3) + ", " +
                    number(ndc.z, 3) + "), outside [-1, 1]: the box is the corners' extent in light view space, "
                    "near = -zmax and far = -zmin, widened if at all, never narrowed (docs: The directional light: an orthographic box fitted to the scene)");
        }
    }
    // A spot light looks at its target whatever its direction: the target lands in
    // the middle of its map, between its near and far planes. Straight down from a
    // point off the world's axis too, where (0, 1, 0) cannot be the up vector.
    struct Spot {
        glm::vec3 position, target;
    };
    const Spot spots[] = {{{4.0f, 12.0f, -3.0f}, {4.0f, 0.0f, -3.0f}},
                          {{-6.0f, 9.0f, 5.0f}, {-6.0f, 0.5f, 5.0f}},
                          {{1.0f, 5.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}},
                          {{3.0f, 6.0f, 8.0f}, {-2.0f, 1.0f, 0.0f}}};
    for (const Spot& spot : spots) {
        const glm::mat4 matrix = stoa::spotLightMatrix(spot.position, spot.target, 50.0f, 0.5f, 40.0f);
        const glm::vec4 clip = matrix * glm::vec4(spot.target, 1.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        const bool finite = std::isfinite(ndc.x) && std::isfinite(ndc.y) && std::isfinite(ndc.z);
        if (!finite || std::abs(ndc.x) > 1e-3f || std::abs(ndc.y) > 1e-3f || std::abs(ndc.z) >= 1.0f)
            return stoa::CheckResult::fail(
                "spotLightMatrix() of a light at (" + number(spot.position.x) + ", " + number(spot.position.y) + ", " +
                number(spot.position.z) + ") looking at (" + number(spot.target.x) + ", " + number(spot.target.y) +
                ", " + number(spot.target.z) + ") puts its target at (" + number(ndc.x, 3) + ", " + number(ndc.y, 3) +
                ", " + number(ndc.z, 3) + "); it belongs in the middle of the map, (0, 0), between near and far. "
                "The up vector is chosen from the direction the light looks in, target - position: (0, 0, 1) when it "
                "is nearly straight up or down (docs: The point light: a perspective frustum)");
    }
    return stoa::CheckResult::pass("the sun's box holds every corner of the scene for four directions, straight down "
                                   "included, and a spot light's target lands in the middle of its map for four "
                                   "directions, straight down included");
}

stoa::CheckResult checkCascadeHoldsItsSlice() {
    const glm::vec3 sceneMin(-40.0f, 0.0f, -40.0f), sceneMax(40.0f, 12.0f, 40.0f);
    const glm::mat4 cameras[] = {
        glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.7f, 0.0f)),
        glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, 2.0f, -5.0f)) *
            glm::rotate(glm::mat4(1.0f), glm::radians(35.0f), glm::vec3(0.0f, 1.0f, 0.0f)) *
            glm::rotate(glm::mat4(1.0f), glm::radians(-20.0f), glm::vec3(1.0f, 0.0f, 0.0f)),
        // High above the scene's box (its top is at y = 12), looking down a little:
        // the whole slice lies nearer the sun than any corner of the box, and the
        // box must still hold it, though no occluder can stand there.
        glm::translate(glm::mat4(1.0f), glm::vec3(-4.0f, 60.0f, 6.0f)) *
            glm::rotate(glm::mat4(1.0f), glm::radians(-15.0f), glm::vec3(1.0f, 0.0f, 0.0f)),
        // Far out along the sun, 150 m from the world's origin: every depth in the
        // light's view is then far below 0, so a margin made from the depths
        // themselves rather than from their range turns negative and narrows the box.
        glm::translate(glm::mat4(1.0f), glm::vec3(150.0f, 2.0f, 150.0f)) *
            glm::rotate(glm::mat4(1.0f), glm::radians(-120.0f), glm::vec3(0.0f, 1.0f, 0.0f)),
    };
    for (const glm::mat4& camera : cameras) {
        const std::array<glm::vec3, 8> corners = transformed(sliceShape(), camera);
        glm::vec3 centre(0.0f);
        for (const glm::vec3& corner : corners) centre += corner / 8.0f;
        std::size_t farthest = 0;
        for (std::size_t k = 1; k < 8; ++k)
            if (glm::length(corners[k] - centre) > glm::length(corners[farthest] - centre)) farthest = k;
        // The sun as usual, and a sun that shines straight from the centre through the
        // corner furthest from it: that corner is then as far from the light as the
        // slice's bounding sphere reaches.
        // And the sun straight overhead, where (0, 1, 0) cannot be the light view's up.
        const glm::vec3 lights[] = {glm::vec3(0.45f, -1.0f, 0.3f), glm::normalize(corners[farthest] - centre),
                                    glm::vec3(0.0f, -1.0f, 0.0f)};
        for (const glm::vec3& light : lights) {
            const glm::mat4 matrix = stoa::cascadeLightMatrix(light, corners, 1024, sceneMin, sceneMax);
            for (const glm::vec3& corner : corners) {
                const glm::vec4 clip = matrix * glm::vec4(corner, 1.0f);
                const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                if (!insideClipCube(ndc))
                    return stoa::CheckResult::fail(
                        "with the light along (" + number(light.x) + ", " + number(light.y) + ", " + number(light.z) +
                        "), the slice's corner (" + number(corner.x) + ", " + number(corner.y) + ", " + number(corner.z) +
                        ") lands at (" + number(ndc.x, 3) + ", " + number(ndc.y, 3) + ", " + number(ndc.z, 3) +
                        ") in the cascade's box, outside [-1, 1]: the box must hold the slice's bounding sphere, its "
                        "far side the sphere's (widened a little, never narrowed) (docs: Fitting each cascade)");
            }
        }
    }
    return stoa::CheckResult::pass("the cascade's box holds every corner of four slices (one above the scene, one far "
                                   "from the world's origin), for "
                                   "the sun overhead, at a slant and shining through the corner furthest from the "
                                   "slice's centre");
}

stoa::CheckResult checkTexelSnapping() {
    const glm::vec3 light(0.45f, -1.0f, 0.3f);
    const glm::vec3 sceneMin(-40.0f, 0.0f, -40.0f), sceneMax(40.0f, 12.0f, 40.0f);
    const int mapSize = 512;
    const glm::vec4 point(1.3f, 0.4f, -6.1f, 1.0f);   // a fixed point of the world
    const std::array<glm::vec3, 8> shape = sliceShape();

    auto texelOf = [&](const glm::mat4& matrix) {
        const glm::vec4 clip = matrix * point;
        return (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * static_cast<float>(mapSize);
    };
    // The box's side in world units: the light view rotates only, so row 0 of the
    // matrix's 3x3 part is 2 / side times a unit vector.
    auto sideOf = [](const glm::mat4& matrix) {
        return 2.0f / glm::length(glm::vec3(matrix[0][0], matrix[1][0], matrix[2][0]));
    };

    const glm::mat4 start = stoa::cascadeLightMatrix(light, transformed(shape, glm::mat4(1.0f)), mapSize, sceneMin, sceneMax);
    const glm::vec2 startTexel = texelOf(start);
    const float side = sideOf(start);
    const float texel = side / static_cast<float>(mapSize);
    const glm::vec3 step(0.0137f, 0.0021f, -0.0093f);   // a camera step well under a texel
    for (int k = 1; k <= 24; ++k) {
        const glm::vec3 moved = step * static_cast<float>(k);
        const glm::mat4 matrix = stoa::cascadeLightMatrix(light, transformed(shape, glm::translate(glm::mat4(1.0f), moved)),
                                                          mapSize, sceneMin, sceneMax);
        const glm::vec2 shift = texelOf(matrix) - startTexel;
        const glm::vec2 fraction = glm::abs(shift - glm::round(shift));
        if (std::max(fraction.x, fraction.y) > 0.02f)
            return stoa::CheckResult::fail("moving the camera by " + number(glm::length(moved) * 100.0f, 1) +
                                           " cm (a texel is " + number(texel * 100.0f, 1) +
                                           " cm) moved a fixed point of the world by (" + number(shift.x) + ", " +
                                           number(shift.y) + ") texels in the map, not by whole texels: the box's "
                                           "origin must move in whole texels (docs: Texel snapping)");
    }
    for (int degrees = 10; degrees <= 80; degrees += 10) {
        const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(static_cast<float>(degrees)), glm::vec3(0.0f, 1.0f, 0.0f));
        const float turnedSide = sideOf(stoa::cascadeLightMatrix(light, transformed(shape, turn), mapSize, sceneMin, sceneMax));
        if (std::abs(turnedSide - side) > 1e-4f * side)
            return stoa::CheckResult::fail("turning the camera by " + std::to_string(degrees) + " degrees changed the box's side from " +
                                           number(side, 3) + " m to " + number(turnedSide, 3) +
                                           " m: the texel size must not depend on where the camera looks, or the "
                                           "shadows swim as it turns (docs: Fitting each cascade, Texel snapping)");
    }
    return stoa::CheckResult::pass("the map moves by whole texels as the camera moves by less than one, and keeps its size as it turns");
}

} // namespace lab05
