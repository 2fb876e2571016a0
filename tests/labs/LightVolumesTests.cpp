// Lab 08's light reach and light-volume state (light_volumes.cpp) against
// independent references:
//   - lightReach against the attenuation formula in double (the brightest
//     channel at the reach is the cut-off, within 1e-4 relative) and against a
//     search for that distance (bracketing by doubling, then bisection), for
//     thousands of random lights; 0 for lights never brighter than the cut-off;
//     linear-only attenuation (q = 0); the wandering lights' documented reach;
//   - lightVolumeState's fields: back faces drawn, the depth test reversed and
//     read-only, lights added up.
// The mistakes of solutions/08_deferred/mistakes/ in light_volumes.cpp each fail
// at least one case here (the GLSL ones are left to the image cases).
// TiledLightsTests.cpp tests the lab's tile lists.

#include "catch.hpp"
#include "TestRandom.hpp"
#include "lab08.hpp"

#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/RenderState.hpp>
#include <stoa/render/DeferredShading.hpp>
#include <stoa/scene/Light.hpp>
#include <stoa/scene/WanderingLights.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using stoa::PointLight;

namespace {

using Random = stoa::test::Random;

std::string describe(const PointLight& light) {
    std::ostringstream out;
    out.precision(9);
    out << "colour (" << light.color.r << ", " << light.color.g << ", " << light.color.b << ") attenuation ("
        << light.attenuation.x << ", " << light.attenuation.y << ", " << light.attenuation.z << ")";
    return out.str();
}

// --- lightReach's references ------------------------------------------------------

// The light's brightest channel at distance d, in double.
double brightness(const PointLight& light, double d) {
    const double peak = std::max({light.color.r, light.color.g, light.color.b});
    const glm::dvec3 a(light.attenuation);
    return peak / (a.x + a.y * d + a.z * d * d);
}

// The distance at which brightness() falls to `cutoff`, found by search: doubling
// until it is at or below the cut-off, then bisection. 0 when it never exceeds it.
double searchedReach(const PointLight& light, double cutoff) {
    if (brightness(light, 0.0) <= cutoff) return 0.0;
    double low = 0.0, high = 1.0;
    while (brightness(light, high) > cutoff) {
        low = high;
        high *= 2.0;
    }
    for (int step = 0; step < 200; ++step) {
        const double middle = 0.5 * (low + high);
        (brightness(light, middle) > cutoff ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

PointLight pointLight(const glm::vec3& color, const glm::vec3& attenuation) {
    PointLight light;
    light.color = color;
    light.attenuation = attenuation;
    return light;
}

} // namespace

// --- lightReach -------------------------------------------------------------------------

TEST_CASE("Lab 08 (deferred): lightReach: the brightest channel at the reach is the cut-off, for thousands of random lights",
          "[lab08][deferred]") {
    Random random(808);
    int reached = 0, dark = 0, failures = 0;
    for (int i = 0; i < 5000; ++i) {
        // One in five dim, so that some are never brighter than the cut-off.
        const float scale = i % 5 == 0 ? random.uniform(0.0f, 0.1f) : 1.0f;
        const PointLight light = pointLight(scale * random.inBox(glm::vec3(0.0f), glm::vec3(3.0f)),
                                            {random.uniform(0.5f, 2.0f), random.uniform(0.0f, 1.0f),
                                             random.uniform(0.05f, 8.0f)});
        const float cutoff = random.uniform(1.0f / 512.0f, 0.25f);
        const float reach = stoa::lightReach(light, cutoff);
        const double expected = searchedReach(light, cutoff);
        bool good;
        if (expected == 0.0) {
            ++dark;
            good = reach == Approx(0.0).margin(1e-6);
        } else {
            ++reached;
            good = reach > 0.0f && brightness(light, reach) == Approx(cutoff).epsilon(1e-4) &&
                   reach == Approx(expected).epsilon(1e-4).margin(1e-5);
        }
        if (!good && ++failures <= 5)
            FAIL_CHECK(describe(light) << ", cut-off " << cutoff << ": reach " << reach << " (brightness there "
                                       << brightness(light, reach) << "), expected " << expected);
    }
    INFO(reached << " lights reach past d = 0, " << dark << " are never brighter than the cut-off");
    CHECK(failures == 0);
    CHECK(reached >= 3800);
    CHECK(dark >= 50);
}

TEST_CASE("Lab 08 (deferred): lightReach is 0 for a light never brighter than the cut-off", "[lab08][deferred]") {
    // Brightest at d = 0: peak / constant.
    CHECK(stoa::lightReach(pointLight(glm::vec3(0.0f), {1.0f, 1.0f, 5.0f}), 1.0f / 64.0f) == Approx(0.0).margin(1e-6));
    CHECK(stoa::lightReach(pointLight({0.01f, 0.005f, 0.0f}, {1.0f, 1.0f, 5.0f}), 1.0f / 64.0f) ==
          Approx(0.0).margin(1e-6));
    CHECK(stoa::lightReach(pointLight({0.02f, 0.02f, 0.02f}, {2.0f, 0.1f, 0.1f}), 1.0f / 64.0f) ==
          Approx(0.0).margin(1e-6));
    // Exactly the cut-off at d = 0 (0.25 / 1 = 0.25): never brighter.
    CHECK(stoa::lightReach(pointLight({0.25f, 0.1f, 0.1f}, {1.0f, 0.5f, 2.0f}), 0.25f) == Approx(0.0).margin(1e-6));
    // Just above it: a short reach, not 0.
    CHECK(stoa::lightReach(pointLight({0.3f, 0.1f, 0.1f}, {1.0f, 0.5f, 2.0f}), 0.25f) > 0.0f);
}

TEST_CASE("Lab 08 (deferred): lightReach with linear attenuation only (q = 0) is (peak / cutoff - constant) / linear",
          "[lab08][deferred]") {
    Random random(64);
    for (int i = 0; i < 500; ++i) {
        const PointLight light = pointLight(random.inBox(glm::vec3(0.05f), glm::vec3(3.0f)),
                                            {random.uniform(0.5f, 2.0f), random.uniform(0.05f, 2.0f), 0.0f});
        const float cutoff = random.uniform(1.0f / 512.0f, 0.02f);   // peak / constant > cut-off
        const double peak = std::max({light.color.r, light.color.g, light.color.b});
        const double expected = (peak / cutoff - light.attenuation.x) / light.attenuation.y;
        const float reach = stoa::lightReach(light, cutoff);
        INFO(describe(light) << ", cut-off " << cutoff);
        REQUIRE(reach == Approx(expected).epsilon(1e-4));
        REQUIRE(brightness(light, reach) == Approx(cutoff).epsilon(1e-4));
    }
}

TEST_CASE("Lab 08 (deferred): lightReach follows the brightest channel, whichever it is", "[lab08][deferred]") {
    const glm::vec3 attenuation(1.0f, 0.7f, 1.8f);
    const float cutoff = 1.0f / 64.0f;
    const float white = stoa::lightReach(pointLight(glm::vec3(2.0f), attenuation), cutoff);
    CHECK(white == Approx(searchedReach(pointLight(glm::vec3(2.0f), attenuation), cutoff)).epsilon(1e-4));
    CHECK(stoa::lightReach(pointLight({2.0f, 0.1f, 0.3f}, attenuation), cutoff) == Approx(white).epsilon(1e-6));
    CHECK(stoa::lightReach(pointLight({0.1f, 2.0f, 0.3f}, attenuation), cutoff) == Approx(white).epsilon(1e-6));
    CHECK(stoa::lightReach(pointLight({0.3f, 0.1f, 2.0f}, attenuation), cutoff) == Approx(white).epsilon(1e-6));
}

TEST_CASE("Lab 08 (deferred): lightReach grows as the cut-off falls", "[lab08][deferred]") {
    const PointLight light = pointLight({1.2f, 0.9f, 0.4f}, {1.0f, 1.0f, 5.0f});
    float previous = 0.0f;
    for (const float cutoff : {0.5f, 0.25f, 0.1f, 1.0f / 16.0f, 1.0f / 64.0f, 1.0f / 256.0f, 1.0f / 1024.0f}) {
        const float reach = stoa::lightReach(light, cutoff);
        INFO("cut-off " << cutoff << ": reach " << reach);
        CHECK(reach > previous);
        previous = reach;
    }
}

TEST_CASE("Lab 08 (deferred): the wandering lights reach between about 3 and 4.5 m at a cut-off of 1/64 (WanderingLights.hpp)",
          "[lab08][deferred]") {
    stoa::WanderingLightsOptions options;
    options.count = 256;
    for (const PointLight& light : stoa::wanderingLights(options, 0.0f)) {
        const float reach = stoa::lightReach(light, 1.0f / 64.0f);
        INFO(describe(light) << ": reach " << reach);
        CHECK(reach >= 3.0f);
        CHECK(reach <= 4.5f);
    }
}

// --- lightVolumeState --------------------------------------------------------------------

TEST_CASE("Lab 08 (deferred): lightVolumeState draws back faces behind the surface, without writing depth, added up",
          "[lab08][deferred]") {
    const stoa::RenderState state = stoa::lightVolumeState();
    // Back faces: one lies behind every covered pixel, also with the camera inside the sphere.
    CHECK(state.cull == stoa::CullMode::Front);
    // The back face lights the surface in front of it: it passes where it is at or behind the stored depth.
    CHECK(state.depth.test);
    const bool reversed = state.depth.func == GL_GEQUAL || state.depth.func == GL_GREATER;
    INFO("depth function 0x" << std::hex << state.depth.func << " (GL_GEQUAL 0x" << GL_GEQUAL << ", GL_GREATER 0x"
                             << GL_GREATER << ")");
    CHECK(reversed);
    // The G-buffer's depth stays as the geometry pass left it, for the next light.
    CHECK_FALSE(state.depth.write);
    // Each light adds to what the ambient pass and the lights before it wrote.
    CHECK(state.blend == stoa::BlendMode::Additive);
    CHECK(state.colorMask.red);
    CHECK(state.colorMask.green);
    CHECK(state.colorMask.blue);
}
