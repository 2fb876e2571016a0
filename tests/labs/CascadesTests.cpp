// Lab 05's cascaded shadow maps (docs/labs/05_shadows.md, "Cascaded shadow
// maps"): the split scheme against its formula, the slice corners against the
// camera's own projection, and each cascade's fit and texel snapping by what
// they must do to points. Texel snapping cannot be seen in a still picture, so
// it is checked here and not by a graded case.

#include "catch.hpp"

#include "lab01.hpp"
#include "lab05.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace {

glm::vec3 project(const glm::mat4& matrix, const glm::vec3& point) {
    const glm::vec4 clip = matrix * glm::vec4(point, 1.0f);
    return glm::vec3(clip) / clip.w;
}

// The large scene's bounds (lab 05's scene = large), written out.
const glm::vec3 kSceneMin(-15.0f, 0.0f, -105.0f);
const glm::vec3 kSceneMax(15.0f, 7.3f, 15.0f);
const glm::vec3 kSun(0.7f, -0.5f, -0.35f);
constexpr int kMapSize = 512;

glm::mat4 cameraView(const glm::vec3& eye) { return glm::lookAt(eye, eye + glm::vec3(0.1f, -0.2f, -1.0f), {0, 1, 0}); }

} // namespace

TEST_CASE("cascadeSplits: near first, far last, increasing", "[lab05][cascades]") {
    for (float lambda : {0.0f, 0.5f, 0.75f, 1.0f}) {
        const std::vector<float> splits = stoa::cascadeSplits(0.1f, 110.0f, 4, lambda);
        REQUIRE(splits.size() == 5);
        CHECK(splits.front() == 0.1f);
        CHECK(splits.back() == 110.0f);
        for (std::size_t i = 1; i < splits.size(); ++i) CHECK(splits[i] > splits[i - 1]);
    }
    const std::vector<float> one = stoa::cascadeSplits(0.5f, 20.0f, 1, 0.5f);
    REQUIRE(one.size() == 2);
    CHECK(one[0] == 0.5f);
    CHECK(one[1] == 20.0f);
}

TEST_CASE("cascadeSplits: lambda 0 is uniform, 1 logarithmic, between a blend", "[lab05][cascades]") {
    const float near = 0.2f, far = 90.0f;
    const std::vector<float> uniform = stoa::cascadeSplits(near, far, 3, 0.0f);
    const std::vector<float> logarithmic = stoa::cascadeSplits(near, far, 3, 1.0f);
    const std::vector<float> practical = stoa::cascadeSplits(near, far, 3, 0.75f);
    for (int i = 0; i <= 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const double t = i / 3.0;
        CHECK(uniform[k] == Approx(near + (far - near) * t).epsilon(1e-5));
        CHECK(logarithmic[k] == Approx(near * std::pow(double(far) / near, t)).epsilon(1e-5));
        CHECK(practical[k] == Approx(0.75 * logarithmic[k] + 0.25 * uniform[k]).epsilon(1e-5));
    }
    // The logarithmic split keeps the first slice much shorter.
    CHECK(logarithmic[1] < 0.1f * uniform[1]);
}

TEST_CASE("frustumSliceCorners: the corners lie on the slice's planes and the camera's frustum",
          "[lab05][cascades]") {
    const glm::mat4 view = cameraView({11.0f, 5.0f, 14.0f});
    const float fov = 50.0f, aspect = 4.0f / 3.0f;
    const auto corners = stoa::frustumSliceCorners(view, fov, aspect, 3.0f, 12.0f);
    const glm::mat4 camera = glm::perspective(glm::radians(fov), aspect, 3.0f, 12.0f) * view;
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 viewPoint = glm::vec3(view * glm::vec4(corners[static_cast<std::size_t>(k)], 1.0f));
        CHECK(-viewPoint.z == Approx((k & 4) ? 12.0f : 3.0f).epsilon(1e-4));
        const glm::vec3 ndc = project(camera, corners[static_cast<std::size_t>(k)]);
        CHECK(ndc.x == Approx((k & 1) ? 1.0f : -1.0f).margin(1e-3));
        CHECK(ndc.y == Approx((k & 2) ? 1.0f : -1.0f).margin(1e-3));
    }
}

TEST_CASE("cascadeLightMatrix: the slice and the casters towards the light are inside the map",
          "[lab05][cascades]") {
    const glm::mat4 view = cameraView({11.0f, 5.0f, 14.0f});
    const std::vector<float> splits = stoa::cascadeSplits(0.1f, 110.0f, 4, 0.75f);
    for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
        const auto corners = stoa::frustumSliceCorners(view, 50.0f, 4.0f / 3.0f, splits[i], splits[i + 1]);
        const glm::mat4 light = stoa::cascadeLightMatrix(kSun, corners, kMapSize, kSceneMin, kSceneMax);
        for (const glm::vec3& corner : corners) {
            const glm::vec3 ndc = project(light, corner);
            CHECK(std::abs(ndc.x) <= 1.0f);
            CHECK(std::abs(ndc.y) <= 1.0f);
            CHECK(std::abs(ndc.z) <= 1.0f);
        }
        // A point of the scene straight towards the light from the slice's
        // centre: inside the depth range, nearer the light than the slice.
        glm::vec3 center(0.0f);
        for (const glm::vec3& corner : corners) center += corner / 8.0f;
        const glm::vec3 towardsLight = center - glm::normalize(kSun) * 10.0f;
        const glm::vec3 occluder = project(light, towardsLight);
        CHECK(occluder.z >= -1.0f);
        CHECK(occluder.z < project(light, center).z);
    }
}

TEST_CASE("cascadeLightMatrix: the map slides in whole texels as the camera moves, keeping its size",
          "[lab05][cascades]") {
    glm::vec2 firstTexel(0.0f);
    float firstWidth = 0.0f;
    for (int step = 0; step < 6; ++step) {
        // Small moves, not multiples of a texel, along and across the view.
        const glm::vec3 eye = glm::vec3(11.0f, 5.0f, 14.0f) + glm::vec3(0.037f, 0.011f, -0.053f) * float(step);
        const auto corners = stoa::frustumSliceCorners(cameraView(eye), 50.0f, 4.0f / 3.0f, 0.1f, 6.0f);
        const glm::mat4 light = stoa::cascadeLightMatrix(kSun, corners, kMapSize, kSceneMin, kSceneMax);
        // A fixed world point's position in texels: only its whole part may change.
        const glm::vec3 ndc = project(light, glm::vec3(10.0f, 0.0f, 8.0f));
        const glm::vec2 texel = (glm::vec2(ndc) * 0.5f + 0.5f) * float(kMapSize);
        const float width = 2.0f / glm::length(glm::vec3(light[0][0], light[1][0], light[2][0]));
        if (step == 0) {
            firstTexel = texel;
            firstWidth = width;
            continue;
        }
        CHECK(width == Approx(firstWidth).epsilon(1e-5));
        const glm::vec2 moved = texel - firstTexel;
        CHECK(std::abs(moved.x - std::round(moved.x)) < 0.02f);
        CHECK(std::abs(moved.y - std::round(moved.y)) < 0.02f);
    }
}

TEST_CASE("cascadeLightMatrix: the box's size does not change as the camera turns", "[lab05][cascades]") {
    const glm::vec3 eye(11.0f, 5.0f, 14.0f);
    float firstWidth = 0.0f;
    for (int yaw = 0; yaw < 360; yaw += 37) {
        const float angle = glm::radians(float(yaw));
        const glm::mat4 view = glm::lookAt(eye, eye + glm::vec3(std::sin(angle), -0.2f, -std::cos(angle)), {0, 1, 0});
        const auto corners = stoa::frustumSliceCorners(view, 50.0f, 4.0f / 3.0f, 2.0f, 15.0f);
        const glm::mat4 light = stoa::cascadeLightMatrix(kSun, corners, kMapSize, kSceneMin, kSceneMax);
        const float width = 2.0f / glm::length(glm::vec3(light[0][0], light[1][0], light[2][0]));
        if (yaw == 0) firstWidth = width;
        CHECK(width == Approx(firstWidth).epsilon(1e-5));
    }
}
