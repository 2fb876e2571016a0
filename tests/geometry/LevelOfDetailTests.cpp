// Levels of detail (lab 06's framework part): fewer triangles level by level,
// made only of the original's vertices, and still a valid mesh.

#include "catch.hpp"

#include <stoa/geometry/LevelOfDetail.hpp>
#include <stoa/geometry/Shapes.hpp>

#include <glm/geometric.hpp>

#include <set>
#include <tuple>

using namespace stoa;

namespace {

// Positions as tuples, to ask whether a level's vertex is one of the original's.
std::set<std::tuple<float, float, float>> positionsOf(const Mesh& mesh) {
    std::set<std::tuple<float, float, float>> positions;
    for (const Vertex& vertex : mesh.vertices)
        positions.emplace(vertex.position.x, vertex.position.y, vertex.position.z);
    return positions;
}

} // namespace

TEST_CASE("LevelOfDetail: each level keeps about its share of the triangles, from the original's vertices") {
    const Mesh sphere = shapes::sphere(1.0f, 48, 24);   // a uv sphere: a seam at u = 0 and poles
    REQUIRE(sphere.triangleCount() > 2000);
    const std::vector<LodLevel> levels = buildLevelsOfDetail(sphere, {1.0f, 0.5f, 0.25f, 0.1f}, 0.2f);
    REQUIRE(levels.size() == 4);
    CHECK(levels[0].mesh.triangleCount() == sphere.triangleCount());
    CHECK(levels[0].relativeError == 0.0f);

    const auto original = positionsOf(sphere);
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const Mesh& level = levels[i].mesh;
        INFO("level " << i << ": " << level.triangleCount() << " of " << sphere.triangleCount() << " triangles");
        CHECK_NOTHROW(level.validate("level"));
        CHECK(level.triangleCount() < levels[i - 1].mesh.triangleCount());
        // Within a fifth of the asked count (the simplifier stops at whole collapses).
        const double asked = levels[i].triangleRatio * static_cast<double>(sphere.triangleCount());
        CHECK(static_cast<double>(level.triangleCount()) <= asked * 1.2);
        CHECK(static_cast<double>(level.triangleCount()) >= asked * 0.5);
        CHECK(levels[i].relativeError > 0.0f);
        CHECK(levels[i].relativeError <= 0.2f);
        for (const Vertex& vertex : level.vertices) {
            CHECK(original.count({vertex.position.x, vertex.position.y, vertex.position.z}) == 1);
            CHECK(glm::length(vertex.position) == Approx(1.0f).margin(1e-4));   // still on the sphere
        }
    }
}

TEST_CASE("LevelOfDetail: a tight error budget stops early, never above the level before") {
    const Mesh sphere = shapes::sphere(1.0f, 32, 16);
    const std::vector<LodLevel> levels = buildLevelsOfDetail(sphere, {0.5f, 0.01f}, 0.001f);
    REQUIRE(levels.size() == 2);
    CHECK(levels[1].mesh.triangleCount() <= levels[0].mesh.triangleCount());
    // 1% of a sphere's triangles cannot stay within 0.1% of its size.
    CHECK(levels[1].mesh.triangleCount() > sphere.triangleCount() / 100);
}
