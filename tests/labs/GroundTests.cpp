// Lab 10's ground functions (labs/10_crowds/student/lab10.hpp) against
// independent references written here, in double:
//   - walkableAt against an interval test per texel in double: at every texel
//     corner and centre and just inside every corner, on a non-square map over a
//     non-square footprint whose cells are powers of two (so the corners are
//     exact in float too), row 0 along z = footprintMin.y, column 0 along
//     x = footprintMin.x, false outside and on the far edges; random points on
//     a 64 x 48 map over [-15, 15]^2 (those within 1e-4 texel of an edge left out);
//   - heightAt against the bilinear blend written as a sum of tent weights
//     over every texel (clamped texel coordinates): exact at the texel centres,
//     the mean of four samples midway between their centres, random points in
//     and around the footprint, the edge values outside it, heightMin and
//     heightMax for values 0 and 1, a 1 x 1 field;
//   - writeExampleGroundMaps (GroundMapMaker.hpp, in the stoa library, hence
//     here) writes exactly the committed assets/crowds maps.
// The planted mistakes of solutions/10_crowds/mistakes/ for these functions each
// fail cases here (checked by applying each one's find/replace to a copy of the solution):
//   map_v_flipped              every walkableAt case but "outside the footprint"
//   heights_nearest            heightAt "midway", "in and around", "values 0 and 1"
// and one the lab dropped: heights_without_half_texel (five heightAt cases).
// BehaviourTests.cpp tests the lab's machines and layers, Md2BlendTests.cpp
// its key frames.

#include "catch.hpp"
#include "TempFolder.hpp"
#include "TestRandom.hpp"
#include "lab10.hpp"

#include <stoa/core/Paths.hpp>
#include <stoa/scene/GroundMapMaker.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace stoa;

namespace {

// The ground: grids, and the references in double.

struct Point {
    double x, z;
};

CollisionMap collisionMap(int width, int height, glm::vec2 min, glm::vec2 max, std::vector<std::uint8_t> walkable) {
    CollisionMap map;
    map.grid = {width, height, min, max};
    map.walkable = std::move(walkable);
    return map;
}

/// The texel whose half-open cell [x0, x0 + cell) x [z0, z0 + cell) holds the point.
bool referenceWalkable(const CollisionMap& map, double x, double z) {
    const GroundGrid& g = map.grid;
    const double cellX = (static_cast<double>(g.footprintMax.x) - g.footprintMin.x) / g.width;
    const double cellZ = (static_cast<double>(g.footprintMax.y) - g.footprintMin.y) / g.height;
    for (int row = 0; row < g.height; ++row) {
        const double z0 = g.footprintMin.y + row * cellZ;
        if (z < z0 || z >= z0 + cellZ) continue;
        for (int col = 0; col < g.width; ++col) {
            const double x0 = g.footprintMin.x + col * cellX;
            if (x >= x0 && x < x0 + cellX) return map.walkable[static_cast<std::size_t>(row * g.width + col)] != 0;
        }
    }
    return false;
}

/// How far (in texels) the point lies from the nearest texel edge along either axis.
double distanceToTexelEdge(const GroundGrid& g, double x, double z) {
    const double u = (x - g.footprintMin.x) / (static_cast<double>(g.footprintMax.x) - g.footprintMin.x) * g.width;
    const double v = (z - g.footprintMin.y) / (static_cast<double>(g.footprintMax.y) - g.footprintMin.y) * g.height;
    return std::min(std::abs(u - std::round(u)), std::abs(v - std::round(v)));
}

/// Bilinear as a sum of tent weights: sample (col, row) at its texel centre
/// weighs max(0, 1 - |u - col|) * max(0, 1 - |v - row|) in clamped texel units.
double referenceHeight(const HeightField& field, double x, double z) {
    const GroundGrid& g = field.grid;
    const double sizeX = static_cast<double>(g.footprintMax.x) - g.footprintMin.x;
    const double sizeZ = static_cast<double>(g.footprintMax.y) - g.footprintMin.y;
    const double u = std::clamp((x - g.footprintMin.x) * g.width / sizeX - 0.5, 0.0, g.width - 1.0);
    const double v = std::clamp((z - g.footprintMin.y) * g.height / sizeZ - 0.5, 0.0, g.height - 1.0);
    double value = 0.0;
    for (int row = 0; row < g.height; ++row) {
        for (int col = 0; col < g.width; ++col) {
            const double weight = std::max(0.0, 1.0 - std::abs(u - col)) * std::max(0.0, 1.0 - std::abs(v - row));
            value += weight * field.values[static_cast<std::size_t>(row * g.width + col)];
        }
    }
    return field.heightMin + (static_cast<double>(field.heightMax) - field.heightMin) * value;
}

Point texelCentre(const GroundGrid& g, int col, int row) {
    const double cellX = (static_cast<double>(g.footprintMax.x) - g.footprintMin.x) / g.width;
    const double cellZ = (static_cast<double>(g.footprintMax.y) - g.footprintMin.y) / g.height;
    return {g.footprintMin.x + (col + 0.5) * cellX, g.footprintMin.y + (row + 0.5) * cellZ};
}

/// 7 x 5 texels of 2 m x 1 m over [-3, 11] x [1, 6], random values, heights -2 .. 5.
HeightField testField(std::uint32_t seed) {
    test::Random random(seed);
    HeightField field;
    field.grid = {7, 5, {-3.0f, 1.0f}, {11.0f, 6.0f}};
    for (int i = 0; i < 7 * 5; ++i) field.values.push_back(random.uniform(0.0f, 1.0f));
    field.heightMin = -2.0f;
    field.heightMax = 5.0f;
    return field;
}

float heightAtPoint(const HeightField& field, Point p) {
    return heightAt(field, glm::vec2(static_cast<float>(p.x), static_cast<float>(p.z)));
}

std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

// walkableAt

TEST_CASE("Lab 10: walkableAt: row 0 lies along z = footprintMin.y, column 0 along x = footprintMin.x",
          "[lab10][crowds]") {
    // 2 x 2 texels over [0, 4] x [10, 14]: only row 0 walkable, then only column 0.
    CollisionMap rows = collisionMap(2, 2, {0.0f, 10.0f}, {4.0f, 14.0f}, {1, 1, 0, 0});
    CHECK(walkableAt(rows, {1.0f, 10.1f}));
    CHECK(walkableAt(rows, {3.0f, 11.9f}));
    CHECK_FALSE(walkableAt(rows, {1.0f, 12.1f}));
    CHECK_FALSE(walkableAt(rows, {3.0f, 13.9f}));
    CollisionMap columns = collisionMap(2, 2, {0.0f, 10.0f}, {4.0f, 14.0f}, {1, 0, 1, 0});
    CHECK(walkableAt(columns, {0.1f, 11.0f}));
    CHECK(walkableAt(columns, {1.9f, 13.0f}));
    CHECK_FALSE(walkableAt(columns, {2.1f, 11.0f}));
    CHECK_FALSE(walkableAt(columns, {3.9f, 13.0f}));
}

TEST_CASE("Lab 10: walkableAt at every texel corner and centre of a non-square map over a non-square footprint",
          "[lab10][crowds]") {
    // 16 x 4 texels of 1 m x 2 m over [-4, 12] x [2, 10]: powers of two, so a
    // corner lands exactly on its texel's edge in float as in double.
    const int width = 16, height = 4;
    std::vector<std::uint8_t> walkable;
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) walkable.push_back((col * 7 + row * 3) % 5 < 2 ? 1 : 0);
    const CollisionMap map = collisionMap(width, height, {-4.0f, 2.0f}, {12.0f, 10.0f}, walkable);
    int checked = 0;
    for (int row = 0; row <= height; ++row) {
        for (int col = 0; col <= width; ++col) {
            const double x = -4.0 + col * 1.0, z = 2.0 + row * 2.0;
            const bool corner = col < width && row < height && walkable[static_cast<std::size_t>(row * width + col)];
            INFO("corner of texel (" << col << ", " << row << ") at (" << x << ", " << z << ")");
            REQUIRE(referenceWalkable(map, x, z) == corner);
            REQUIRE(walkableAt(map, {static_cast<float>(x), static_cast<float>(z)}) == corner);
            // Just inside each texel that meets at this corner.
            for (const auto& offset : {Point{0.01, 0.02}, Point{-0.01, 0.02}, Point{0.01, -0.02}, Point{-0.01, -0.02}}) {
                const double px = x + offset.x, pz = z + offset.z;
                INFO("at (" << px << ", " << pz << ")");
                REQUIRE(walkableAt(map, {static_cast<float>(px), static_cast<float>(pz)}) ==
                        referenceWalkable(map, px, pz));
                ++checked;
            }
            if (col < width && row < height) {
                const Point centre = texelCentre(map.grid, col, row);
                REQUIRE(walkableAt(map, {static_cast<float>(centre.x), static_cast<float>(centre.z)}) == corner);
            }
        }
    }
    CHECK(checked == 4 * (width + 1) * (height + 1));
}

TEST_CASE("Lab 10: walkableAt is false outside the footprint, and on its far edges", "[lab10][crowds]") {
    const CollisionMap map = collisionMap(4, 2, {-2.0f, -1.0f}, {2.0f, 3.0f}, std::vector<std::uint8_t>(8, 1));
    CHECK(walkableAt(map, {-2.0f, -1.0f}));   // the near corner belongs to texel (0, 0)
    CHECK(walkableAt(map, {1.99f, 2.99f}));
    for (const glm::vec2 p : {glm::vec2(-2.01f, 0.0f), glm::vec2(2.0f, 0.0f), glm::vec2(2.5f, 0.0f), glm::vec2(0.0f, -1.01f),
                              glm::vec2(0.0f, 3.0f), glm::vec2(0.0f, 30.0f), glm::vec2(-100.0f, -100.0f),
                              glm::vec2(2.0f, 3.0f), glm::vec2(-3.0f, 4.0f)}) {
        INFO("at (" << p.x << ", " << p.y << ")");
        CHECK_FALSE(walkableAt(map, p));
    }
}

TEST_CASE("Lab 10: walkableAt agrees with the reference on random points of a 64 x 48 map", "[lab10][crowds]") {
    test::Random random(3030);
    const int width = 64, height = 48;
    std::vector<std::uint8_t> walkable;
    for (int i = 0; i < width * height; ++i) walkable.push_back(random.chance(0.5f) ? 1 : 0);
    const CollisionMap map = collisionMap(width, height, {-15.0f, -15.0f}, {15.0f, 15.0f}, walkable);
    int compared = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec2 p(random.uniform(-16.0f, 16.0f), random.uniform(-16.0f, 16.0f));
        if (distanceToTexelEdge(map.grid, p.x, p.y) < 1e-4) continue;
        INFO("at (" << p.x << ", " << p.y << ")");
        REQUIRE(walkableAt(map, p) == referenceWalkable(map, p.x, p.y));
        ++compared;
    }
    CHECK(compared > 19800);
}

// heightAt

TEST_CASE("Lab 10: heightAt is the texel's value at its centre, mapped to [heightMin, heightMax]", "[lab10][crowds]") {
    const HeightField field = testField(4040);
    for (int row = 0; row < field.grid.height; ++row) {
        for (int col = 0; col < field.grid.width; ++col) {
            const double value = field.values[static_cast<std::size_t>(row * field.grid.width + col)];
            const double want = -2.0 + 7.0 * value;
            INFO("texel (" << col << ", " << row << ")");
            CHECK(std::abs(heightAtPoint(field, texelCentre(field.grid, col, row)) - want) < 1e-5);
        }
    }
}

TEST_CASE("Lab 10: heightAt midway between four texel centres is their mean", "[lab10][crowds]") {
    const HeightField field = testField(5050);
    const auto value = [&](int col, int row) { return field.values[static_cast<std::size_t>(row * field.grid.width + col)]; };
    for (int row = 0; row + 1 < field.grid.height; ++row) {
        for (int col = 0; col + 1 < field.grid.width; ++col) {
            const Point a = texelCentre(field.grid, col, row), b = texelCentre(field.grid, col + 1, row + 1);
            const double mean = 0.25 * (value(col, row) + value(col + 1, row) + value(col, row + 1) + value(col + 1, row + 1));
            INFO("between texels (" << col << ", " << row << ") and (" << col + 1 << ", " << row + 1 << ")");
            CHECK(std::abs(heightAtPoint(field, {0.5 * (a.x + b.x), 0.5 * (a.z + b.z)}) - (-2.0 + 7.0 * mean)) < 1e-5);
            // A quarter of the way along x on row `row`'s centre line.
            const double along = 0.75 * value(col, row) + 0.25 * value(col + 1, row);
            CHECK(std::abs(heightAtPoint(field, {0.75 * a.x + 0.25 * b.x, a.z}) - (-2.0 + 7.0 * along)) < 1e-5);
        }
    }
}

TEST_CASE("Lab 10: heightAt agrees with the reference in and around the footprint", "[lab10][crowds]") {
    for (const std::uint32_t seed : {6060u, 6061u}) {
        const HeightField field = testField(seed);
        test::Random random(seed);
        for (int i = 0; i < 5000; ++i) {
            const glm::vec2 p(random.uniform(-7.0f, 15.0f), random.uniform(-1.0f, 8.0f));
            INFO("seed " << seed << ", at (" << p.x << ", " << p.y << ")");
            REQUIRE(std::abs(heightAt(field, p) - referenceHeight(field, p.x, p.y)) < 2e-5);
        }
    }
    // A square field over a square footprint, as the example worlds have.
    HeightField square;
    square.grid = {64, 64, {-30.0f, -30.0f}, {30.0f, 30.0f}};
    test::Random random(6062);
    for (int i = 0; i < 64 * 64; ++i) square.values.push_back(random.uniform(0.0f, 1.0f));
    square.heightMax = 6.0f;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec2 p(random.uniform(-31.0f, 31.0f), random.uniform(-31.0f, 31.0f));
        INFO("at (" << p.x << ", " << p.y << ")");
        REQUIRE(std::abs(heightAt(square, p) - referenceHeight(square, p.x, p.y)) < 2e-5);
    }
}

TEST_CASE("Lab 10: heightAt is clamped to the edge texels outside their centres", "[lab10][crowds]") {
    const HeightField field = testField(7070);
    const GroundGrid& g = field.grid;
    const auto height = [&](int col, int row) {
        return -2.0 + 7.0 * field.values[static_cast<std::size_t>(row * g.width + col)];
    };
    for (int row = 0; row < g.height; ++row) {
        const double z = texelCentre(g, 0, row).z;
        for (const double x : {-3.0, -2.5, -50.0}) CHECK(std::abs(heightAtPoint(field, {x, z}) - height(0, row)) < 1e-5);
        for (const double x : {11.0, 10.5, 50.0})
            CHECK(std::abs(heightAtPoint(field, {x, z}) - height(g.width - 1, row)) < 1e-5);
    }
    for (int col = 0; col < g.width; ++col) {
        const double x = texelCentre(g, col, 0).x;
        for (const double z : {1.0, 1.25, -40.0}) CHECK(std::abs(heightAtPoint(field, {x, z}) - height(col, 0)) < 1e-5);
        for (const double z : {6.0, 5.75, 40.0})
            CHECK(std::abs(heightAtPoint(field, {x, z}) - height(col, g.height - 1)) < 1e-5);
    }
    CHECK(std::abs(heightAtPoint(field, {-9.0, -9.0}) - height(0, 0)) < 1e-5);
    CHECK(std::abs(heightAtPoint(field, {99.0, 99.0}) - height(g.width - 1, g.height - 1)) < 1e-5);
    CHECK(std::abs(heightAtPoint(field, {99.0, -9.0}) - height(g.width - 1, 0)) < 1e-5);
}

TEST_CASE("Lab 10: heightAt maps values 0 and 1 to heightMin and heightMax", "[lab10][crowds]") {
    HeightField field;
    field.grid = {2, 2, {0.0f, 0.0f}, {2.0f, 2.0f}};
    field.values = {0.0f, 1.0f, 0.25f, 0.75f};
    field.heightMin = 3.0f;
    field.heightMax = 11.0f;
    CHECK(heightAt(field, {0.5f, 0.5f}) == Approx(3.0));
    CHECK(heightAt(field, {1.5f, 0.5f}) == Approx(11.0));
    CHECK(heightAt(field, {0.5f, 1.5f}) == Approx(5.0));
    CHECK(heightAt(field, {1.5f, 1.5f}) == Approx(9.0));
    CHECK(heightAt(field, {1.0f, 1.0f}) == Approx(7.0));
    field.heightMin = -4.0f;
    field.heightMax = -4.0f;
    CHECK(heightAt(field, {1.3f, 0.2f}) == Approx(-4.0));
}

TEST_CASE("Lab 10: heightAt on a 1 x 1 field is its one value everywhere", "[lab10][crowds]") {
    HeightField field;
    field.grid = {1, 1, {-15.0f, -15.0f}, {15.0f, 15.0f}};
    field.values = {0.4f};
    field.heightMin = 1.0f;
    field.heightMax = 3.0f;
    for (const glm::vec2 p : {glm::vec2(0.0f), glm::vec2(-15.0f), glm::vec2(14.9f, -3.0f), glm::vec2(40.0f, -70.0f)})
        CHECK(heightAt(field, p) == Approx(1.8));
    field.values = {0.0f};   // what loadGroundMaps gives a world without a height map
    field.heightMin = field.heightMax = 0.0f;
    CHECK(heightAt(field, {3.0f, 4.0f}) == 0.0f);
}

// The maps the example worlds use.

TEST_CASE("Lab 10: writeExampleGroundMaps writes exactly the committed maps", "[lab10][crowds]") {
    const test::TempFolder folder("crowd-maps");
    const std::vector<std::filesystem::path> written = writeExampleGroundMaps(folder.path());
    std::vector<std::string> names;
    for (const std::filesystem::path& path : written) names.push_back(path.filename().string());
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"acropolis_collision.png", "hills_collision.png", "hills_height.png"});
    for (const std::filesystem::path& path : written) {
        const std::filesystem::path committed = paths::assetsDir() / "crowds" / path.filename();
        INFO(path.filename().string() << " against " << committed.string());
        REQUIRE(std::filesystem::exists(committed));
        CHECK(readBytes(path) == readBytes(committed));
    }
}
