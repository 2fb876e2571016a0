// DebugLines: boxes, spheres and frustums as segments, each where it belongs.

#include "catch.hpp"

#include <stoa/geometry/DebugLines.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

using namespace stoa;

TEST_CASE("DebugLines: a box has 12 edges of its sides' lengths; a sphere's circles lie on it") {
    DebugLines lines;
    lines.box(Aabb{{-1.0f, 0.0f, 2.0f}, {1.0f, 3.0f, 6.0f}}, {1, 0, 0});
    REQUIRE(lines.lineCount() == 12);
    int alongX = 0, alongY = 0, alongZ = 0;
    for (std::size_t i = 0; i < lines.vertices().size(); i += 2) {
        const glm::vec3 edge = lines.vertices()[i + 1].position - lines.vertices()[i].position;
        alongX += edge == glm::vec3(2, 0, 0);
        alongY += edge == glm::vec3(0, 3, 0);
        alongZ += edge == glm::vec3(0, 0, 4);
    }
    CHECK((alongX == 4 && alongY == 4 && alongZ == 4));

    lines.clear();
    CHECK(lines.lineCount() == 0);
    lines.sphere(BoundingSphere{{1.0f, 2.0f, 3.0f}, 0.5f}, {0, 1, 0}, 16);
    CHECK(lines.lineCount() == 3 * 16);
    for (const LineVertex& end : lines.vertices())
        CHECK(glm::length(end.position - glm::vec3(1, 2, 3)) == Approx(0.5f).margin(1e-5));
}

TEST_CASE("DebugLines: a frustum's corners are what the view-projection maps to the clip cube's corners") {
    const glm::mat4 view = glm::lookAt(glm::vec3(3, 2, 5), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.5f, 0.5f, 20.0f);
    const glm::mat4 viewProjection = projection * view;
    DebugLines lines;
    lines.frustum(viewProjection, {1, 1, 1});
    REQUIRE(lines.lineCount() == 12);
    for (const LineVertex& end : lines.vertices()) {
        const glm::vec4 clip = viewProjection * glm::vec4(end.position, 1.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        for (int axis = 0; axis < 3; ++axis) CHECK(std::abs(ndc[axis]) == Approx(1.0f).margin(1e-3));
    }
    // The near corners are near/far times closer to the eye than the far ones.
    float nearest = 1e9f, furthest = 0.0f;
    for (const LineVertex& end : lines.vertices()) {
        const float depth = -(view * glm::vec4(end.position, 1.0f)).z;
        nearest = std::min(nearest, depth);
        furthest = std::max(furthest, depth);
    }
    CHECK(nearest == Approx(0.5f).epsilon(1e-3));
    CHECK(furthest == Approx(20.0f).epsilon(1e-3));
}
