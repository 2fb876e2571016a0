// Lab 06's levels of detail (level_of_detail.cpp) against independent references:
//   - the projected size against glm::perspective: the point one radius above the
//     centre, projected, in pixels;
//   - the level bands.
// The mistakes of solutions/06_culling/mistakes/ in level_of_detail.cpp each fail
// at least one case here. BoundsTests.cpp and FrustumTests.cpp test the lab's
// culling math; tests/geometry/LevelOfDetailTests.cpp the framework's simplified
// meshes.

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab06.hpp"

#include <stoa/geometry/Bounds.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using stoa::BoundingSphere;

namespace {

using Random = stoa::test::Random;

// The projected radius in pixels, through glm: a camera at `eye` looking at the
// sphere's centre; the point one radius above the centre (along the camera's
// up) projected; the NDC y difference times half the viewport's height.
double projectedRadiusPixels(const BoundingSphere& sphere, const glm::vec3& eye, float fovYDegrees, int height) {
    const glm::dvec3 center(sphere.center), from(eye);
    glm::dvec3 upHint(0.0, 1.0, 0.0);
    if (std::abs(glm::dot(glm::normalize(center - from), upHint)) > 0.99) upHint = glm::dvec3(1.0, 0.0, 0.0);
    const glm::dmat4 view = glm::lookAt(from, center, upHint);
    const glm::dmat4 projection = glm::perspective(glm::radians(static_cast<double>(fovYDegrees)), 1.5, 0.01, 1e5);
    const glm::dvec3 cameraUp(view[0][1], view[1][1], view[2][1]);
    const auto ndcY = [&](const glm::dvec3& p) {
        const glm::dvec4 clip = projection * view * glm::dvec4(p, 1.0);
        return clip.y / clip.w;
    };
    const double dy = ndcY(center + static_cast<double>(sphere.radius) * cameraUp) - ndcY(center);
    return dy * 0.5 * height;
}

double expectedQuality(double pixels, const stoa::LodSettings& settings) {
    const double q = (pixels - settings.hiddenBelowPixels) / (settings.fullDetailPixels - settings.hiddenBelowPixels);
    return std::clamp(q, 0.0, 1.0);
}

} // namespace

// --- level_of_detail.cpp ----------------------------------------------------

TEST_CASE("Lab 06: lodQuality agrees with the projected radius through glm::perspective", "[lab06][lod]") {
    Random random(77);
    const stoa::LodSettings defaults;
    const std::vector<stoa::LodSettings> settingsList = {defaults, {0.0f, 40.0f}, {5.0f, 200.0f}};
    int inRange = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const stoa::LodSettings& settings = settingsList[trial % settingsList.size()];
        const float fov = random.uniform(20.0f, 100.0f);
        const int height = 240 + static_cast<int>(random.uniform(0.0f, 1200.0f));
        const glm::vec3 eye = random.inBox(glm::vec3(-50.0f), glm::vec3(50.0f));
        const float distance = random.uniform(2.0f, 300.0f);
        // Small r / d (at most 0.1), where the formula and the projection agree.
        const float radius = distance * random.uniform(0.0005f, 0.1f);
        const BoundingSphere sphere{eye + distance * random.unitVector(), radius};
        const double pixels = projectedRadiusPixels(sphere, eye, fov, height);
        const double expected = expectedQuality(pixels, settings);
        const float quality = stoa::lodQuality(sphere, eye, fov, height, settings);
        INFO("trial " << trial << ": fov " << fov << ", height " << height << ", r " << radius << ", d " << distance
                      << ", " << pixels << " px");
        CHECK(quality >= 0.0f);
        CHECK(quality <= 1.0f);
        CHECK(std::abs(quality - expected) <= 0.01 * std::max(expected, 0.01));
        if (expected > 0.02 && expected < 0.98) ++inRange;
    }
    CHECK(inRange >= 150);   // most draws land between the two thresholds
}

TEST_CASE("Lab 06: lodQuality is 0 at hiddenBelowPixels, 1 at fullDetailPixels, linear between, clamped",
          "[lab06][lod]") {
    const float fov = 50.0f;
    const int height = 720;
    const glm::vec3 eye(3.0f, 1.7f, -4.0f);
    const glm::vec3 direction = glm::normalize(glm::vec3(1.0f, -0.2f, 2.0f));
    const float radius = 1.5f;
    const double pixelsPerRadiusOverDistance = 0.5 * height / std::tan(0.5 * glm::radians(static_cast<double>(fov)));
    // The distance at which the sphere's projected radius is `pixels`.
    const auto at = [&](double pixels) {
        const float distance = static_cast<float>(pixelsPerRadiusOverDistance * radius / pixels);
        return BoundingSphere{eye + distance * direction, radius};
    };
    for (const stoa::LodSettings& settings : {stoa::LodSettings{}, stoa::LodSettings{10.0f, 50.0f}}) {
        INFO("hidden " << settings.hiddenBelowPixels << ", full " << settings.fullDetailPixels);
        CHECK(stoa::lodQuality(at(settings.hiddenBelowPixels), eye, fov, height, settings) == Approx(0.0f).margin(1e-4));
        CHECK(stoa::lodQuality(at(settings.fullDetailPixels), eye, fov, height, settings) == Approx(1.0f).margin(1e-4));
        const double middle = 0.5 * (settings.hiddenBelowPixels + settings.fullDetailPixels);
        CHECK(stoa::lodQuality(at(middle), eye, fov, height, settings) == Approx(0.5f).margin(1e-4));
        const double quarter = settings.hiddenBelowPixels + 0.25 * (settings.fullDetailPixels - settings.hiddenBelowPixels);
        CHECK(stoa::lodQuality(at(quarter), eye, fov, height, settings) == Approx(0.25f).margin(1e-4));
        // Beyond the thresholds: clamped.
        CHECK(stoa::lodQuality(at(0.5 * settings.hiddenBelowPixels + 0.01), eye, fov, height, settings) == 0.0f);
        CHECK(stoa::lodQuality(at(3.0 * settings.fullDetailPixels), eye, fov, height, settings) == 1.0f);
        CHECK(stoa::lodQuality({eye + 1e5f * direction, radius}, eye, fov, height, settings) == 0.0f);
        // Just outside the sphere: huge on the screen, still 1.
        CHECK(stoa::lodQuality({eye + 1.01f * radius * direction, radius}, eye, fov, height, settings) == 1.0f);
    }
}

TEST_CASE("Lab 06: lodQuality is 1 with the eye inside the sphere, its centre included", "[lab06][lod]") {
    const glm::vec3 eye(10.0f, 2.0f, -7.0f);
    CHECK(stoa::lodQuality({eye, 0.5f}, eye, 60.0f, 720) == 1.0f);
    CHECK(stoa::lodQuality({eye + glm::vec3(0.3f, 0.0f, 0.0f), 0.5f}, eye, 60.0f, 720) == 1.0f);
    CHECK(stoa::lodQuality({eye + glm::vec3(0.0f, 0.0f, -4.0f), 4.0f}, eye, 45.0f, 480) == 1.0f);
    // Even with thresholds it could not otherwise reach.
    CHECK(stoa::lodQuality({eye + glm::vec3(0.0f, 1.0f, 0.0f), 2.0f}, eye, 60.0f, 10, {100.0f, 1000.0f}) == 1.0f);
}

TEST_CASE("Lab 06: lodQuality grows with the viewport's height and shrinks with the field of view and distance",
          "[lab06][lod]") {
    const glm::vec3 eye(0.0f);
    const BoundingSphere sphere{{0.0f, 0.0f, -60.0f}, 1.0f};
    const float base = stoa::lodQuality(sphere, eye, 50.0f, 720);
    CHECK(base > 0.0f);
    CHECK(base < 1.0f);
    CHECK(stoa::lodQuality(sphere, eye, 50.0f, 1080) > base);
    CHECK(stoa::lodQuality(sphere, eye, 70.0f, 720) < base);
    CHECK(stoa::lodQuality({{0.0f, 0.0f, -80.0f}, 1.0f}, eye, 50.0f, 720) < base);
    // 0.5 * 720 / tan(25 deg) / 60 = 12.87 px: (12.87 - 2) / 78.
    CHECK(base == Approx((0.5 * 720.0 / std::tan(glm::radians(25.0)) / 60.0 - 2.0) / 78.0).epsilon(1e-4));
}

TEST_CASE("Lab 06: levelOfDetail: -1 for no quality, 0 for full, the bands in between", "[lab06][lod]") {
    for (int levels = 1; levels <= 6; ++levels) {
        INFO(levels << " levels");
        CHECK(stoa::levelOfDetail(0.0f, levels) == -1);
        CHECK(stoa::levelOfDetail(-0.5f, levels) == -1);
        CHECK(stoa::levelOfDetail(-0.0f, levels) == -1);
        CHECK(stoa::levelOfDetail(std::numeric_limits<float>::quiet_NaN(), levels) == -1);
        CHECK(stoa::levelOfDetail(1.0f, levels) == 0);
        CHECK(stoa::levelOfDetail(1e-6f, levels) == levels - 1);
        CHECK(stoa::levelOfDetail(std::numeric_limits<float>::denorm_min(), levels) == levels - 1);
        CHECK(stoa::levelOfDetail(std::numeric_limits<float>::min(), levels) == levels - 1);
        // Monotone: more quality never a coarser level; always a level that exists.
        int previous = stoa::levelOfDetail(1e-7f, levels);
        for (int step = 1; step <= 20000; ++step) {
            const float quality = static_cast<float>(step) / 20000.0f;
            const int level = stoa::levelOfDetail(quality, levels);
            if (level > previous || level < 0 || level >= levels) {
                FAIL_CHECK("quality " << quality << ": level " << level << " after " << previous);
                break;
            }
            previous = level;
        }
        // The independent band: level k for quality in (1 - (k+1)/n, 1 - k/n].
        for (int step = 1; step <= 1000; ++step) {
            const double quality = (step - 0.5) / 1000.0;   // never on a band's edge
            const int expected = std::min(levels - 1, static_cast<int>((1.0 - quality) * levels));
            const int level = stoa::levelOfDetail(static_cast<float>(quality), levels);
            if (level != expected) {
                FAIL_CHECK("quality " << quality << ": level " << level << ", expected " << expected);
                break;
            }
        }
    }
}

// Quality in (0.75, 1] gives level 0, (0.5, 0.75] level 1, (0.25, 0.5] level 2, (0, 0.25] level 3.
TEST_CASE("Lab 06: levelOfDetail with 4 levels: 0 down to 0.75 exclusive, then 1 to 0.5, 2 to 0.25, 3 to 0",
          "[lab06][lod]") {
    CHECK(stoa::levelOfDetail(1.0f, 4) == 0);
    CHECK(stoa::levelOfDetail(0.9f, 4) == 0);
    CHECK(stoa::levelOfDetail(0.7501f, 4) == 0);
    CHECK(stoa::levelOfDetail(0.75f, 4) == 1);
    CHECK(stoa::levelOfDetail(0.6f, 4) == 1);
    CHECK(stoa::levelOfDetail(0.5001f, 4) == 1);
    CHECK(stoa::levelOfDetail(0.5f, 4) == 2);
    CHECK(stoa::levelOfDetail(0.4f, 4) == 2);
    CHECK(stoa::levelOfDetail(0.2501f, 4) == 2);
    CHECK(stoa::levelOfDetail(0.25f, 4) == 3);
    CHECK(stoa::levelOfDetail(0.1f, 4) == 3);
    CHECK(stoa::levelOfDetail(0.0001f, 4) == 3);
    CHECK(stoa::levelOfDetail(0.0f, 4) == -1);
}
