// Lab 05's light-space matrices, checked by what they must do to points
// (docs/labs/05_shadows.md, "The light-space matrix") and against glm.

#include "catch.hpp"

#include "lab05.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

glm::vec3 project(const glm::mat4& matrix, const glm::vec3& point) {
    const glm::vec4 clip = matrix * glm::vec4(point, 1.0f);
    return glm::vec3(clip) / clip.w;
}

std::vector<glm::vec3> corners(const glm::vec3& low, const glm::vec3& high) {
    std::vector<glm::vec3> result;
    for (int corner = 0; corner < 8; ++corner)
        result.emplace_back((corner & 1) ? high.x : low.x, (corner & 2) ? high.y : low.y, (corner & 4) ? high.z : low.z);
    return result;
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// The Acropolis's bounds (AcropolisScene.hpp), written out: no assets needed here.
const glm::vec3 kSceneMin(-15.0f, 0.0f, -15.0f);
const glm::vec3 kSceneMax(15.0f, 7.3f, 15.0f);

} // namespace

TEST_CASE("directionalLightMatrix maps the scene's bounds inside [-1, 1]^3 and touches the x and y sides") {
    const glm::vec3 directions[] = {{-0.45f, -0.5f, -0.75f}, {0.3f, -1.0f, 0.2f}, {1.0f, -0.15f, 0.0f}};
    for (const glm::vec3& direction : directions) {
        CAPTURE(direction.x, direction.y, direction.z);
        const glm::mat4 light = stoa::directionalLightMatrix(direction, kSceneMin, kSceneMax);
        REQUIRE(finite(light));
        glm::vec3 low(INFINITY), high(-INFINITY);
        for (const glm::vec3& corner : corners(kSceneMin, kSceneMax)) {
            const glm::vec3 ndc = project(light, corner);
            low = glm::min(low, ndc);
            high = glm::max(high, ndc);
        }
        // Fitted: the box spans the map exactly in x and y (every texel is used) ...
        CHECK(low.x == Approx(-1.0f).margin(1e-4));
        CHECK(high.x == Approx(1.0f).margin(1e-4));
        CHECK(low.y == Approx(-1.0f).margin(1e-4));
        CHECK(high.y == Approx(1.0f).margin(1e-4));
        // ... and lies inside the depth range, none of it clipped.
        CHECK(low.z >= -1.0f);
        CHECK(high.z <= 1.0f);
        CHECK(high.z - low.z > 1.5f);   // not squeezed into a sliver of the depth range
    }
}

TEST_CASE("directionalLightMatrix is orthographic along the light's direction") {
    const glm::vec3 direction(-0.45f, -0.5f, -0.75f);
    const glm::mat4 light = stoa::directionalLightMatrix(direction, kSceneMin, kSceneMax);
    // w stays 1: parallel rays, no perspective divide.
    CHECK(light[0][3] == Approx(0.0f).margin(1e-6));
    CHECK(light[1][3] == Approx(0.0f).margin(1e-6));
    CHECK(light[2][3] == Approx(0.0f).margin(1e-6));
    CHECK(light[3][3] == Approx(1.0f).margin(1e-6));
    // Points along one ray of light land on the same texel, deeper the further the light travelled.
    const glm::vec3 start(2.0f, 6.0f, -1.0f);
    const glm::vec3 travelled = start + 4.0f * glm::normalize(direction);
    const glm::vec3 a = project(light, start), b = project(light, travelled);
    CHECK(b.x == Approx(a.x).margin(1e-5));
    CHECK(b.y == Approx(a.y).margin(1e-5));
    CHECK(b.z > a.z);
}

TEST_CASE("directionalLightMatrix ignores the length of the direction") {
    const glm::vec3 direction(0.3f, -1.0f, 0.2f);
    const glm::mat4 unit = stoa::directionalLightMatrix(glm::normalize(direction), kSceneMin, kSceneMax);
    const glm::mat4 longer = stoa::directionalLightMatrix(7.0f * direction, kSceneMin, kSceneMax);
    for (const glm::vec3& corner : corners(kSceneMin, kSceneMax)) {
        const glm::vec3 a = project(unit, corner), b = project(longer, corner);
        CHECK(glm::length(a - b) < 1e-4f);
    }
}

TEST_CASE("directionalLightMatrix handles a sun straight overhead") {
    const glm::mat4 light = stoa::directionalLightMatrix({0.0f, -1.0f, 0.0f}, kSceneMin, kSceneMax);
    REQUIRE(finite(light));
    // Looking straight down, the top of the box is nearer the light than the floor below it.
    const glm::vec3 top = project(light, {1.0f, 7.0f, 2.0f});
    const glm::vec3 floor = project(light, {1.0f, 0.0f, 2.0f});
    CHECK(top.z < floor.z);
    CHECK(top.x == Approx(floor.x).margin(1e-5));
    CHECK(top.y == Approx(floor.y).margin(1e-5));
}

TEST_CASE("spotLightMatrix matches glm's perspective and look-at with a square map") {
    const glm::vec3 position(4.0f, 9.0f, 6.0f), target(0.0f, 1.0f, 0.0f);
    const float fov = 70.0f, zNear = 0.5f, zFar = 40.0f;
    const glm::mat4 light = stoa::spotLightMatrix(position, target, fov, zNear, zFar);
    const glm::mat4 expected = glm::perspective(glm::radians(fov), 1.0f, zNear, zFar) *
                               glm::lookAt(position, target, glm::vec3(0.0f, 1.0f, 0.0f));
    for (const glm::vec3& point : corners({-3.0f, 0.0f, -3.0f}, {3.0f, 4.0f, 3.0f}))
        CHECK(glm::length(project(light, point) - project(expected, point)) < 1e-4f);
}

TEST_CASE("spotLightMatrix puts the target in the map's centre and near, far at depth -1, 1") {
    const glm::vec3 position(-2.0f, 8.0f, 3.0f), target(1.0f, 0.0f, -1.0f);
    const float zNear = 0.5f, zFar = 30.0f;
    const glm::mat4 light = stoa::spotLightMatrix(position, target, 90.0f, zNear, zFar);
    const glm::vec3 axis = glm::normalize(target - position);
    const glm::vec3 centre = project(light, target);
    CHECK(centre.x == Approx(0.0f).margin(1e-5));
    CHECK(centre.y == Approx(0.0f).margin(1e-5));
    CHECK(project(light, position + zNear * axis).z == Approx(-1.0f).margin(1e-4));
    CHECK(project(light, position + zFar * axis).z == Approx(1.0f).margin(1e-3));
}

TEST_CASE("spotLightMatrix handles a light straight above its target") {
    const glm::mat4 light = stoa::spotLightMatrix({0.0f, 10.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 60.0f, 1.0f, 20.0f);
    REQUIRE(finite(light));
    const glm::vec3 below = project(light, {0.0f, 2.0f, 0.0f});
    CHECK(below.x == Approx(0.0f).margin(1e-5));
    CHECK(below.y == Approx(0.0f).margin(1e-5));
    // At the edge of a 60-degree cone: 8 m below the light, 8 tan(30) to the side.
    const glm::vec3 edge = project(light, {8.0f * std::tan(glm::radians(30.0f)), 2.0f, 0.0f});
    CHECK(std::max(std::abs(edge.x), std::abs(edge.y)) == Approx(1.0f).margin(1e-4));
}
