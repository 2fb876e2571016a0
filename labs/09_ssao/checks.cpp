// Lab 09's property checks; see checks.hpp. A kernel drawn in another order is
// still a fine kernel, so the pictures hardly change (by one case's worth);
// but it is not the kernel of the seed, and a kernel built from three draws in
// one expression is a different kernel under another compiler. The expected
// samples below are those of the docs' order, printed by the course's solution.

#include "checks.hpp"
#include "lab09.hpp"

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/render/AmbientOcclusion.hpp>
#include <stoa/render/AmbientOcclusionPass.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/scene/DrawList.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace lab09 {

namespace {

std::string vectorText(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6f, %.6f, %.6f)", v.x, v.y, v.z);
    return text;
}

// ssaoKernel(4, 1): the kernel of the seed the graded cases use, four samples.
const glm::vec3 kExpected[] = {{-0.00589053659f, 0.00146378891f, 0.000178154834f},
                               {-0.00685488805f, 0.012752967f, 0.0361817591f},
                               {-0.0505420119f, -0.0281486083f, 0.0127045847f},
                               {-0.0964893475f, 0.260949939f, 0.203060687f}};

// Whether `sample` points where sample `index` of seed 1 would with its first three
// numbers in another order than x, y, z (the three draws in one expression).
bool drawnInAnotherOrder(const glm::vec3& sample, int index) {
    stoa::KernelRandom random(1);
    for (int skip = 0; skip < 4 * index; ++skip) random.next();
    const float u[3] = {random.next(), random.next(), random.next()};
    if (glm::length(sample) < 1e-9f) return false;
    const glm::vec3 direction = glm::normalize(sample);
    int order[3] = {0, 1, 2};
    while (std::next_permutation(order, order + 3)) {   // every order but x, y, z
        const glm::vec3 other(2.0f * u[order[0]] - 1.0f, 2.0f * u[order[1]] - 1.0f, u[order[2]]);
        if (glm::length(direction - glm::normalize(other)) < 1e-4f) return true;
    }
    return false;
}

} // namespace

stoa::CheckResult checkKernelInOrder() {
    const std::vector<glm::vec3> kernel = stoa::ssaoKernel(4, 1);
    if (kernel.size() != 4)
        return stoa::CheckResult::fail("ssaoKernel(4, 1) returned " + std::to_string(kernel.size()) +
                                       " samples, expected 4 (docs: The sample kernel)");
    for (int i = 0; i < 4; ++i) {
        if (glm::length(kernel[i] - kExpected[i]) <= 1e-4f * glm::length(kExpected[i])) continue;
        const std::string found = "ssaoKernel(4, 1): sample " + std::to_string(i) + " is " + vectorText(kernel[i]) +
                                  ", expected " + vectorText(kExpected[i]);
        if (drawnInAnotherOrder(kernel[i], i))
            return stoa::CheckResult::fail(
                found + ": its direction is that of its first three numbers in another order than x, y, z. "
                        "Draw each in a statement of its own: the arguments of one call, such as "
                        "glm::vec3(next(), next(), next()), may be evaluated in any order (docs: The sample kernel)");
        return stoa::CheckResult::fail(found + " (docs: The sample kernel, its four steps)");
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

std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
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
    const std::string what = "a wall pixel beside the edge of a strip " + number(stripZ - wallZ) +
                             " m in front of the wall, radius " + number(radius) +
                             ", one sample that lands behind the strip: the raw occlusion is " + number(got) +
                             ", expected " + number(expected) + " (the range check, smoothstep(0, 1, r / |P.z - sceneZ|) = " +
                             number(1.0f - expected) + ")";
    if (std::abs(got - expected) <= 0.03f)
        return stoa::CheckResult::pass("the range check weighs an occluder by its distance from P: 0.5 at 2 radii");
    if (std::abs(got - fromTheSample) <= 0.03f)
        return stoa::CheckResult::fail(what + "; " + number(got) + " is what |S.z - sceneZ|, the sample's distance, gives: "
                                              "the range check measures from P (docs: The range check)");
    return stoa::CheckResult::fail(what + " (docs: The occlusion estimate, The range check)");
}

} // namespace lab09
