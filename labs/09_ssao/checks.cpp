// Lab 09's property checks; see checks.hpp. A kernel drawn in another order is
// still a fine kernel, so the pictures hardly change (a case or two, only just);
// but it is not the kernel of the seed, and a kernel built from three draws in
// one expression is a different kernel under another compiler. The check holds
// no stored answer: it draws the seed's numbers from KernelRandom itself and
// tests the direction the docs' first two steps give, not the lengths.

#include "checks.hpp"
#include "lab09.hpp"

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/render/AmbientOcclusion.hpp>
#include <stoa/render/AmbientOcclusionPass.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/scene/DrawList.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace lab09 {

namespace {

// The direction of (2a - 1, 2b - 1, c): steps 1 and 2 of the docs for the numbers a, b, c.
glm::vec3 directionOf(float a, float b, float c) {
    return glm::normalize(glm::vec3(2.0f * a - 1.0f, 2.0f * b - 1.0f, c));
}

} // namespace

stoa::CheckResult checkKernelInOrder() {
    constexpr int kSamples = 4;
    const std::vector<glm::vec3> kernel = stoa::ssaoKernel(kSamples, 1);
    if (kernel.size() != kSamples)
        return stoa::CheckResult::fail("ssaoKernel(4, 1) returned " + std::to_string(kernel.size()) +
                                       " samples, expected 4 (docs: The sample kernel)");
    stoa::KernelRandom random(1);
    for (int i = 0; i < kSamples; ++i) {
        // Sample i's four numbers: u[0..2] for the direction, u[3] for the length.
        std::array<float, 4> u{};
        for (float& number : u) number = random.next();
        const glm::vec3 sample = kernel[static_cast<std::size_t>(i)];
        const glm::vec3 expected = directionOf(u[0], u[1], u[2]);
        if (!(glm::length(sample) > 0.0f) || !std::isfinite(glm::length(sample)))
            return stoa::CheckResult::fail("ssaoKernel(4, 1): sample " + std::to_string(i) + " is " + stoa::checkVector(sample, 4) +
                                           ", which has no direction (docs: The sample kernel)");
        const glm::vec3 direction = glm::normalize(sample);
        if (glm::length(direction - expected) <= 1e-4f) continue;
        const std::string found = "ssaoKernel(4, 1): sample " + std::to_string(i) + " points along " +
                                  stoa::checkVector(direction, 4) + ", expected " + stoa::checkVector(expected, 4) +
                                  ", the direction of (2u - 1, 2u - 1, u) for its first three numbers of seed 1";
        std::array<int, 3> order{0, 1, 2};
        while (std::next_permutation(order.begin(), order.end()))   // every order but x, y, z
            if (glm::length(direction - directionOf(u[order[0]], u[order[1]], u[order[2]])) <= 1e-4f)
                return stoa::CheckResult::fail(
                    found + ": yours are the same three numbers in another order. Draw each in a statement of its "
                            "own: the arguments of one call, such as glm::vec3(next(), next(), next()), may be "
                            "evaluated in any order (docs: The sample kernel)");
        return stoa::CheckResult::fail(found + " (docs: The sample kernel, its first two steps)");
    }
    return stoa::CheckResult::pass("the kernel of seed 1 is drawn in the docs' order: x, y, z, then the length");
}

namespace {

// A square of side `size` facing the camera (+Z), its centre at `centre`.
stoa::DrawItem facingTheCamera(const stoa::GpuMesh& square, glm::vec3 centre) {
    stoa::DrawItem item;
    item.mesh = &square;
    item.model = glm::translate(glm::mat4(1.0f), centre) *
                 glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));   // +Y to +Z
    item.normalMatrix = glm::mat3(item.model);
    return item;
}

float smoothstep01(float x) {
    const float t = std::min(std::max(x, 0.0f), 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

} // namespace

stoa::CheckResult checkRangeCheckFromThePoint(stoa::DeferredRenderer& renderer, stoa::AmbientOcclusionPass& occlusion) {
    // The camera at the origin looks down -Z. The wall at z = -10; the strip at
    // z = -9, from x = -10 to its edge at x = 0, which every depth projects to
    // the middle column. Radius 0.5: the strip is 2 radii in front of the wall.
    const float radius = 0.5f, wallZ = -10.0f, stripZ = -9.0f;
    const glm::ivec2 size(64, 64);
    const stoa::GpuMesh square(stoa::shapes::plane(1.0f, 1));
    stoa::DrawItem wall = facingTheCamera(square, glm::vec3(0.0f, 0.0f, wallZ));
    wall.model = wall.model * glm::scale(glm::mat4(1.0f), glm::vec3(40.0f, 1.0f, 40.0f));
    stoa::DrawItem strip = facingTheCamera(square, glm::vec3(-5.0f, 0.0f, stripZ));
    strip.model = strip.model * glm::scale(glm::mat4(1.0f), glm::vec3(10.0f, 1.0f, 40.0f));
    stoa::FirstPersonCamera camera(glm::vec3(0.0f), 0.0f, 0.0f);
    camera.setProjection(60.0f, 0.5f, 50.0f);

    // One sample, 0.8 r to the left and 0.6 r towards the camera; the noise turns nothing
    // (every random vector along +X, so the frame of a wall facing the camera is x, y, z).
    const glm::vec3 sample(-0.8f, 0.0f, 0.6f);
    occlusion.setKernel({sample}, std::vector<glm::vec3>(16, glm::vec3(1.0f, 0.0f, 0.0f)));
    renderer.renderGeometry({wall, strip}, camera, size);
    occlusion.render(renderer, size, {radius, 0.025f});
    const stoa::Image raw = occlusion.rawTarget().readColor();
    stoa::Framebuffer::bindDefault();

    // The first column of wall right of the middle: P.x = 0.09 m; S.x = P.x - 0.4 lands on the strip.
    const float got = raw.pixel(size.x / 2, size.y / 2).r / 255.0f;
    const float sampleZ = wallZ + radius * sample.z;
    const float expected = 1.0f - smoothstep01(radius / std::abs(wallZ - stripZ));   // 0.5
    const float fromTheSample = 1.0f - smoothstep01(radius / std::abs(sampleZ - stripZ));
    const std::string what = "a wall pixel beside the edge of a strip " + stoa::checkNumber(stripZ - wallZ) +
                             " m in front of the wall, radius " + stoa::checkNumber(radius) +
                             ", one sample that lands behind the strip: the raw occlusion is " + stoa::checkNumber(got) +
                             ", expected " + stoa::checkNumber(expected) + " (the range check, smoothstep(0, 1, r / |P.z - sceneZ|) = " +
                             stoa::checkNumber(1.0f - expected) + ")";
    if (std::abs(got - expected) <= 0.03f)
        return stoa::CheckResult::pass("the range check weighs an occluder by its distance from P: 0.5 at 2 radii");
    if (std::abs(got - fromTheSample) <= 0.03f)
        return stoa::CheckResult::fail(what + "; " + stoa::checkNumber(got) + " is what |S.z - sceneZ|, the sample's distance, gives: "
                                              "the range check measures from P (docs: The range check)");
    return stoa::CheckResult::fail(what + " (docs: The occlusion estimate, The range check)");
}

stoa::CheckResult checkBlurFootprint(stoa::DeferredRenderer& renderer, stoa::AmbientOcclusionPass& occlusion) {
    // A picture whose sides are no multiple of 4, so the window meets every edge
    // at every offset. Draw once to size the pass's targets, then replace the raw
    // occlusion with random levels and blur them.
    const glm::ivec2 size(37, 29);
    const stoa::GpuMesh square(stoa::shapes::plane(1.0f, 1));
    stoa::DrawItem wall = facingTheCamera(square, glm::vec3(0.0f, 0.0f, -10.0f));
    wall.model = wall.model * glm::scale(glm::mat4(1.0f), glm::vec3(40.0f, 1.0f, 40.0f));
    stoa::FirstPersonCamera camera(glm::vec3(0.0f), 0.0f, 0.0f);
    camera.setProjection(60.0f, 0.5f, 50.0f);
    occlusion.setKernel({glm::vec3(0.0f, 0.0f, 0.5f)}, std::vector<glm::vec3>(16, glm::vec3(1.0f, 0.0f, 0.0f)));
    renderer.renderGeometry({wall}, camera, size);
    occlusion.render(renderer, size, {0.5f, 0.025f});

    // Levels row by row from the bottom, as OpenGL counts rows and gl_FragCoord does.
    std::vector<std::uint8_t> levels(static_cast<std::size_t>(size.x * size.y));
    stoa::CheckRandom random(20261129u);
    for (std::uint8_t& level : levels) level = random.nextByte();
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_2D, occlusion.raw().id()));
    STOA_GL_CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 1));
    STOA_GL_CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size.x, size.y, GL_RED, GL_UNSIGNED_BYTE, levels.data()));
    STOA_GL_CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 4));
    occlusion.blur();
    const stoa::Image blurred = occlusion.blurredTarget().readColor();   // row 0 at the top
    stoa::Framebuffer::bindDefault();

    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            float sum = 0.0f;
            int kept = 0;
            for (int dy = -2; dy <= 1; ++dy)
                for (int dx = -2; dx <= 1; ++dx) {
                    const int px = x + dx, py = y + dy;
                    if (px < 0 || py < 0 || px >= size.x || py >= size.y) continue;
                    sum += levels[static_cast<std::size_t>(py * size.x + px)];
                    ++kept;
                }
            const float expected = sum / static_cast<float>(kept);
            const float got = blurred.pixel(x, size.y - 1 - y).r;
            if (std::abs(got - expected) > 1.01f)
                return stoa::CheckResult::fail(
                    "the blur of random levels (0 to 255) on a " + std::to_string(size.x) + " x " + std::to_string(size.y) +
                    " picture gives " + stoa::checkNumber(got, 1) + " at pixel (" + std::to_string(x) + ", " +
                    std::to_string(y) + ") (gl_FragCoord, rows from the bottom); the mean of the " +
                    std::to_string(kept) + " pixels of its 4 x 4 window inside the picture is " +
                    stoa::checkNumber(expected, 1) + ". The window's offsets run from -2 to 1 on each axis, and "
                    "only neighbours outside the picture are left out (docs: The blur)");
        }
    }
    return stoa::CheckResult::pass("the blur is the mean of the 4 x 4 window (offsets -2 to 1) inside the picture at "
                                   "every pixel of a 37 x 29 picture of random levels, edges and corners included");
}

} // namespace lab09
