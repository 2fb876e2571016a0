// Lab 08's tile lists (tiled_lights.cpp) against independent references:
//   - lightTileRange against brute force: the ray through every pixel's centre,
//     from the near plane to the far plane, tested against the sphere in double;
//     every pixel it meets must lie in a tile of the range, and the range must
//     not be much wider than those pixels. Random spheres in front of the camera,
//     across the near plane and off the screen, on pictures whose last row and
//     column of tiles are cut short; and the cases named in the header: behind
//     or nearer than the near plane, across it, far off the screen, clamped;
//   - buildTileLightLists against lists built here from lightTileRange and the
//     tiles' depth ranges (the sphere's span of distances against the tile's),
//     with every depth open, random depths and sky, and lights just short of a
//     tile's surfaces or just reaching them, from in front and from behind.
// Near-grazing rays are left out of the exact comparisons by a margin (the
// sphere shrunk by 1e-4 of its radius), and counted.
// The mistakes of solutions/08_deferred/mistakes/ in tiled_lights.cpp each fail
// at least one case here. LightVolumesTests.cpp tests the lab's light volumes.

#include "catch.hpp"
#include "TestRandom.hpp"
#include "lab08.hpp"

#include <stoa/render/DeferredShading.hpp>
#include <stoa/scene/Light.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using stoa::DepthRange;
using stoa::LightSphere;
using stoa::TileGrid;
using stoa::TileLightLists;
using stoa::TileRange;

namespace {

using Random = stoa::test::Random;

std::string describe(const LightSphere& sphere) {
    std::ostringstream out;
    out.precision(9);
    out << "sphere at (" << sphere.centerView.x << ", " << sphere.centerView.y << ", " << sphere.centerView.z
        << ") radius " << sphere.reach;
    return out.str();
}

std::string describe(const TileRange& range) {
    std::ostringstream out;
    if (range.empty()) out << "empty range ";
    out << "columns " << range.first.x << ".." << range.last.x << ", rows " << range.first.y << ".." << range.last.y;
    return out.str();
}

// --- the views the tile tests look through -------------------------------------------

struct TestView {
    std::string name;
    float fovYDegrees, near, far;
    TileGrid grid;
    int sphereCount;   // how many random spheres the brute-force test draws for it
    float aspect() const { return static_cast<float>(grid.viewport.x) / static_cast<float>(grid.viewport.y); }
    glm::mat4 projection() const { return glm::perspective(glm::radians(fovYDegrees), aspect(), near, far); }
    double tanHalfY() const { return std::tan(glm::radians(static_cast<double>(fovYDegrees)) * 0.5); }
    double tanHalfX() const { return tanHalfY() * static_cast<double>(aspect()); }
};

TileGrid tileGrid(glm::ivec2 viewport, int tileSize) {
    TileGrid grid;
    grid.viewport = viewport;
    grid.tileSize = tileSize;
    return grid;
}

std::vector<TestView> testViews() {
    return {
        {"60 deg, 400x300, 16-pixel tiles (the last row cut short), near 0.1", 60.0f, 0.1f, 100.0f,
         tileGrid({400, 300}, 16), 400},
        {"90 deg, 100x70, 16-pixel tiles (the last row and column cut short), near 0.5", 90.0f, 0.5f, 50.0f,
         tileGrid({100, 70}, 16), 1000},
        {"35 deg, 256x256, 32-pixel tiles, near 1", 35.0f, 1.0f, 500.0f, tileGrid({256, 256}, 32), 400},
        {"50 deg, 90x200 (portrait), 8-pixel tiles (the last column cut short), near 0.3", 50.0f, 0.3f, 80.0f,
         tileGrid({90, 200}, 8), 600},
        {"70 deg, 1280x720, 16-pixel tiles (the benchmark's), near 0.1", 70.0f, 0.1f, 200.0f,
         tileGrid({1280, 720}, 16), 48},
    };
}

// The ray through each pixel's centre (pixels counted from the bottom left, as
// gl_FragCoord), as a unit direction from the eye and the distances along it at
// which it crosses the near and far planes: built from the inverse of the
// projection, in double.
struct PixelRays {
    glm::ivec2 viewport;
    std::vector<glm::dvec3> direction;
    std::vector<double> nearDistance, farDistance;

    explicit PixelRays(const TestView& view) : viewport(view.grid.viewport) {
        const glm::dmat4 inverse = glm::inverse(glm::dmat4(view.projection()));
        const std::size_t count = static_cast<std::size_t>(viewport.x) * static_cast<std::size_t>(viewport.y);
        direction.reserve(count);
        nearDistance.reserve(count);
        farDistance.reserve(count);
        for (int y = 0; y < viewport.y; ++y)
            for (int x = 0; x < viewport.x; ++x) {
                const glm::dvec2 ndc((x + 0.5) / viewport.x * 2.0 - 1.0, (y + 0.5) / viewport.y * 2.0 - 1.0);
                const glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, -1.0, 1.0);
                const glm::dvec4 farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
                const glm::dvec3 onNear = glm::dvec3(nearPoint) / nearPoint.w;
                const glm::dvec3 onFar = glm::dvec3(farPoint) / farPoint.w;
                direction.push_back(glm::normalize(onNear));
                nearDistance.push_back(glm::length(onNear));
                farDistance.push_back(glm::length(onFar));
            }
    }

    /// Whether pixel i's ray, between the near and far planes, passes within `radius` of `center`.
    bool hits(std::size_t i, const glm::dvec3& center, double radius) const {
        const double along = std::clamp(glm::dot(center, direction[i]), nearDistance[i], farDistance[i]);
        const glm::dvec3 offset = center - direction[i] * along;
        return glm::dot(offset, offset) <= radius * radius;
    }
};

bool rangeHolds(const TileRange& range, glm::ivec2 tile) {
    return !range.empty() && tile.x >= range.first.x && tile.x <= range.last.x && tile.y >= range.first.y &&
           tile.y <= range.last.y;
}

// A sphere whose centre lies on the ray through `ndc` (which may be off the
// picture) at view depth `depth`.
LightSphere sphereAt(const TestView& view, glm::dvec2 ndc, double depth, double radius) {
    LightSphere sphere;
    sphere.centerView = glm::vec3(ndc.x * view.tanHalfX() * depth, ndc.y * view.tanHalfY() * depth, -depth);
    sphere.reach = static_cast<float>(radius);
    return sphere;
}

// Which pixels a sphere covers, by brute force.
struct Footprint {
    int pixels = 0;                        // whose ray meets the sphere, shrunk by the margin
    int grazing = 0;                       // whose ray meets the sphere but not the shrunk one
    glm::ivec2 low{1 << 30}, high{-1};     // the box of the pixels met (margin included)
    bool touchesEdge = false;              // a pixel met lies in the picture's first or last row or column
    std::vector<glm::ivec2> outside;       // pixels met (shrunk sphere) in no tile of the range: at most 5
    int outsideCount = 0;
};

constexpr double kGrazingMargin = 1e-4;    // of the radius

Footprint footprint(const PixelRays& rays, const TileGrid& grid, const LightSphere& sphere, const TileRange& range) {
    Footprint result;
    const glm::dvec3 center(sphere.centerView);
    const double radius = sphere.reach;
    std::size_t i = 0;
    for (int y = 0; y < rays.viewport.y; ++y)
        for (int x = 0; x < rays.viewport.x; ++x, ++i) {
            if (!rays.hits(i, center, radius * (1.0 + kGrazingMargin))) continue;
            result.low = glm::min(result.low, glm::ivec2(x, y));
            result.high = glm::max(result.high, glm::ivec2(x, y));
            if (x == 0 || y == 0 || x == rays.viewport.x - 1 || y == rays.viewport.y - 1) result.touchesEdge = true;
            if (!rays.hits(i, center, radius * (1.0 - kGrazingMargin))) {
                ++result.grazing;
                continue;
            }
            ++result.pixels;
            if (!rangeHolds(range, glm::ivec2(x, y) / grid.tileSize)) {
                if (result.outside.size() < 5) result.outside.emplace_back(x, y);
                ++result.outsideCount;
            }
        }
    return result;
}

void checkClampedToGrid(const TileRange& range, const TileGrid& grid) {
    if (range.empty()) return;
    const glm::ivec2 last = grid.tiles() - 1;
    INFO(describe(range) << " on a grid of " << grid.tiles().x << "x" << grid.tiles().y << " tiles");
    CHECK(range.first.x >= 0);
    CHECK(range.first.y >= 0);
    CHECK(range.last.x <= last.x);
    CHECK(range.last.y <= last.y);
}

} // namespace

// --- lightTileRange ----------------------------------------------------------------------

TEST_CASE("Lab 08 (deferred): lightTileRange holds every pixel whose ray meets the sphere, for random spheres (brute force)",
          "[lab08][deferred]") {
    Random random(2808);
    for (const TestView& view : testViews()) {
        INFO(view.name);
        const glm::mat4 projection = view.projection();
        const PixelRays rays(view);
        const glm::ivec2 tiles = view.grid.tiles();
        int seen = 0, unseen = 0, acrossNear = 0, checkedTight = 0, grazing = 0, misses = 0, loose = 0;
        for (int i = 0; i < view.sphereCount; ++i) {
            // Centres through a point of (or beyond) the picture, from just past the near
            // plane to half the far one; radii from a speck to most of the depth. One in
            // eight about the near plane (many across it), three in eight small and on the
            // picture (for the width check).
            const float spread = i % 8 >= 1 && i % 8 <= 3 ? 0.8f : 1.6f;
            const glm::dvec2 ndc(random.uniform(-spread, spread), random.uniform(-spread, spread));
            double depth, radius;
            if (i % 8 == 0) {
                depth = view.near * random.uniform(0.3f, 3.0f);
                radius = view.near * random.uniform(0.05f, 2.5f);
            } else {
                depth = view.near * std::exp(random.uniform(0.0f, 1.0f) * std::log(0.5 * view.far / view.near));
                radius = depth * (spread < 1.0f ? random.uniform(0.003f, 0.15f) : random.uniform(0.003f, 0.7f));
            }
            const LightSphere sphere = sphereAt(view, ndc, depth, radius);
            const TileRange range = stoa::lightTileRange(sphere, projection, view.near, view.grid);
            INFO(describe(sphere) << ": " << describe(range));
            checkClampedToGrid(range, view.grid);
            const Footprint covered = footprint(rays, view.grid, sphere, range);
            grazing += covered.grazing;
            if (sphere.centerView.z + sphere.reach > -view.near) ++acrossNear;
            (covered.pixels > 0 ? seen : unseen) += 1;
            if (covered.outsideCount > 0) {
                ++misses;
                std::ostringstream pixels;
                for (const glm::ivec2 pixel : covered.outside)
                    pixels << " (" << pixel.x << ", " << pixel.y << ") in tile (" << pixel.x / view.grid.tileSize << ", "
                           << pixel.y / view.grid.tileSize << ")";
                if (misses <= 5)
                    FAIL_CHECK(covered.outsideCount << " of " << covered.pixels
                                                    << " pixels the sphere covers lie outside the range, e.g." << pixels.str());
            }
            // Not much wider than the pixels it covers: for a sphere wholly past the near
            // plane, at least 4 radii away and wholly on the picture, within the covered
            // pixels' box widened by its own size and a tile on each side. (Projecting the
            // sphere's bounding cube, for one, stays well within that.)
            const double distance = glm::length(glm::dvec3(sphere.centerView));
            if (covered.pixels > 0 && !covered.touchesEdge && distance >= 4.0 * radius &&
                sphere.centerView.z + sphere.reach < -view.near) {
                ++checkedTight;
                const glm::ivec2 size = covered.high - covered.low + 1;
                const glm::ivec2 lowest = glm::max(covered.low - size - view.grid.tileSize, glm::ivec2(0));
                const glm::ivec2 highest = glm::min(covered.high + size + view.grid.tileSize, view.grid.viewport - 1);
                const bool tight = !range.empty() && glm::all(glm::greaterThanEqual(range.first, lowest / view.grid.tileSize)) &&
                                   glm::all(glm::lessThanEqual(range.last, highest / view.grid.tileSize));
                if (!tight && ++loose <= 5)
                    FAIL_CHECK("the range is far wider than the pixels covered, (" << covered.low.x << ", " << covered.low.y
                                                                                  << ") .. (" << covered.high.x << ", "
                                                                                  << covered.high.y << ")");
            }
        }
        INFO(seen << " spheres on the picture (" << checkedTight << " checked for width), " << unseen << " off it, "
                  << acrossNear << " across the near plane; " << grazing << " grazing pixels left out; tiles "
                  << tiles.x << "x" << tiles.y);
        CHECK(misses == 0);
        CHECK(loose == 0);
        // The draw exercised what it is meant to.
        CHECK(seen >= view.sphereCount / 3);
        CHECK(unseen >= view.sphereCount / 40);
        CHECK(acrossNear >= view.sphereCount / 40);
        CHECK(checkedTight >= view.sphereCount / 5);
    }
}

TEST_CASE("Lab 08 (deferred): lightTileRange is empty for a sphere nearer than the near plane or behind the camera",
          "[lab08][deferred]") {
    const TestView view = testViews()[1];   // near 0.5
    const glm::mat4 projection = view.projection();
    const std::vector<LightSphere> spheres{
        {{0.0f, 0.0f, -0.2f}, 0.1f},      // between the eye and the near plane
        {{0.0f, 0.0f, -0.45f}, 0.04f},    // just short of it
        {{0.1f, 0.05f, -0.3f}, 0.19f},
        {{0.0f, 0.0f, 0.0f}, 0.3f},       // about the eye
        {{0.0f, 0.0f, 2.0f}, 1.0f},       // behind the camera
        {{0.0f, 0.0f, 10.0f}, 9.9f},      // behind, large, its front just short of the eye
        {{3.0f, 1.0f, 5.0f}, 2.0f},
        {{-40.0f, 25.0f, 30.0f}, 20.0f},
    };
    for (const LightSphere& sphere : spheres) {
        const TileRange range = stoa::lightTileRange(sphere, projection, view.near, view.grid);
        INFO(describe(sphere) << ": " << describe(range));
        CHECK(range.empty());
    }
}

TEST_CASE("Lab 08 (deferred): lightTileRange of a sphere across the near plane in front of the eye is every tile",
          "[lab08][deferred]") {
    for (const TestView& view : testViews()) {
        INFO(view.name);
        // Centred on the near plane, holding the whole near rectangle: every pixel's ray starts inside it.
        const double corner = view.near * std::sqrt(view.tanHalfX() * view.tanHalfX() + view.tanHalfY() * view.tanHalfY());
        for (const double radius : {1.5 * corner, 3.0 * corner}) {
            const LightSphere sphere{{0.0f, 0.0f, -view.near}, static_cast<float>(radius)};
            const TileRange range = stoa::lightTileRange(sphere, view.projection(), view.near, view.grid);
            INFO(describe(sphere) << ": " << describe(range));
            CHECK(range.first == glm::ivec2(0));
            CHECK(range.last == view.grid.tiles() - 1);
        }
    }
}

TEST_CASE("Lab 08 (deferred): lightTileRange is empty for a sphere far off the screen", "[lab08][deferred]") {
    for (const TestView& view : testViews()) {
        INFO(view.name);
        const PixelRays rays(view);
        for (const glm::dvec2 ndc : {glm::dvec2(4, 0), glm::dvec2(-4, 0), glm::dvec2(0, 4), glm::dvec2(0, -4),
                                     glm::dvec2(3, 3), glm::dvec2(-3, 3), glm::dvec2(3, -3), glm::dvec2(-3, -3)}) {
            const double depth = 20.0 * view.near;
            const LightSphere sphere = sphereAt(view, ndc, depth, 0.1 * depth);
            const TileRange range = stoa::lightTileRange(sphere, view.projection(), view.near, view.grid);
            INFO(describe(sphere) << ": " << describe(range));
            REQUIRE(footprint(rays, view.grid, sphere, range).pixels == 0);   // the reference agrees it is off
            CHECK(range.empty());
        }
    }
}

TEST_CASE("Lab 08 (deferred): lightTileRange is clamped to the grid, the cut-short last row and column included",
          "[lab08][deferred]") {
    const TestView view = testViews()[1];   // 100x70 pixels, 16-pixel tiles: 7x5, the last holding 4x6 pixels
    const glm::mat4 projection = view.projection();
    const glm::ivec2 last = view.grid.tiles() - 1;
    REQUIRE(last == glm::ivec2(6, 4));
    const PixelRays rays(view);
    const auto ndcOfPixel = [&](glm::dvec2 pixel) { return pixel / glm::dvec2(view.grid.viewport) * 2.0 - 1.0; };

    SECTION("a small sphere on the top-right corner pixel: the last tile, and no further") {
        const LightSphere sphere = sphereAt(view, ndcOfPixel({99.5, 69.5}), 5.0, 0.02);
        const TileRange range = stoa::lightTileRange(sphere, projection, view.near, view.grid);
        INFO(describe(sphere) << ": " << describe(range));
        REQUIRE(footprint(rays, view.grid, sphere, range).outsideCount == 0);
        CHECK(range.last == last);
        CHECK(range.first.x >= last.x - 1);
        CHECK(range.first.y >= last.y - 1);
    }
    SECTION("a sphere half off the top-right corner: the last tile") {
        const LightSphere sphere = sphereAt(view, {1.0, 1.0}, 5.0, 0.8);
        const TileRange range = stoa::lightTileRange(sphere, projection, view.near, view.grid);
        INFO(describe(sphere) << ": " << describe(range));
        REQUIRE(footprint(rays, view.grid, sphere, range).outsideCount == 0);
        CHECK(range.last == last);
        CHECK(range.first.x > 0);
        CHECK(range.first.y > 0);
    }
    SECTION("a sphere half off the bottom-left corner: the first tile") {
        const LightSphere sphere = sphereAt(view, {-1.0, -1.0}, 5.0, 0.8);
        const TileRange range = stoa::lightTileRange(sphere, projection, view.near, view.grid);
        INFO(describe(sphere) << ": " << describe(range));
        REQUIRE(footprint(rays, view.grid, sphere, range).outsideCount == 0);
        CHECK(range.first == glm::ivec2(0));
        CHECK(range.last.x < last.x);
        CHECK(range.last.y < last.y);
    }
    SECTION("a sphere wider than the picture, wholly past the near plane: every tile, and no more") {
        const LightSphere sphere{{0.0f, 0.0f, -10.0f}, 9.4f};   // 70 deg about the axis; the picture's corners at 60
        const TileRange range = stoa::lightTileRange(sphere, projection, view.near, view.grid);
        INFO(describe(sphere) << ": " << describe(range));
        REQUIRE(footprint(rays, view.grid, sphere, range).outsideCount == 0);
        CHECK(range.first == glm::ivec2(0));
        CHECK(range.last == last);
    }
}

TEST_CASE("Lab 08 (deferred): lightTileRange of a small, distant sphere in the middle is a few tiles about the middle",
          "[lab08][deferred]") {
    const TestView view = testViews()[4];   // 1280x720, 16-pixel tiles
    // 0.25 m at 20 m through 70 degrees: about 6 pixels in radius.
    const LightSphere sphere{{0.0f, 0.0f, -20.0f}, 0.25f};
    const TileRange range = stoa::lightTileRange(sphere, view.projection(), view.near, view.grid);
    INFO(describe(sphere) << ": " << describe(range));
    CHECK(rangeHolds(range, {40, 22}));   // pixel (640, 360)
    CHECK(range.last.x - range.first.x + 1 <= 3);
    CHECK(range.last.y - range.first.y + 1 <= 3);
}

// --- buildTileLightLists -----------------------------------------------------------------

namespace {

// Random lights about a view's frustum, one in ten behind the eye.
std::vector<LightSphere> randomLights(const TestView& view, Random& random, int count) {
    std::vector<LightSphere> lights;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 ndc(random.uniform(-1.4f, 1.4f), random.uniform(-1.4f, 1.4f));
        const double depth = view.near * std::exp(random.uniform(-1.0f, 1.0f) * std::log(0.2 * view.far / view.near));
        lights.push_back(sphereAt(view, ndc, depth, depth * random.uniform(0.01f, 0.4f)));
        if (i % 10 == 0) lights.back().centerView.z = -lights.back().centerView.z;
    }
    return lights;
}

// Every tile sees every depth: only the ranges decide.
std::vector<DepthRange> openDepths(const TileGrid& grid) {
    DepthRange everything;
    everything.nearest = 0.0f;
    everything.farthest = 1e30f;
    return std::vector<DepthRange>(static_cast<std::size_t>(grid.tileCount()), everything);
}

// Whether the light belongs in a tile with depths `depths`, by the header's rule:
// its sphere's distances, -z - reach .. -z + reach, overlap the tile's. Within
// `margin` of either end it may go either way.
enum class Verdict { In, Out, EitherWay };

Verdict depthVerdict(const LightSphere& light, const DepthRange& depths) {
    if (depths.empty()) return Verdict::Out;
    const double distance = -static_cast<double>(light.centerView.z), reach = light.reach;
    const double margin = 1e-5 * (std::abs(distance) + reach + depths.farthest);
    const double gapBehind = (distance - reach) - depths.farthest;   // > 0: the sphere begins past the farthest surface
    const double gapInFront = depths.nearest - (distance + reach);   // > 0: the sphere ends before the nearest surface
    if (gapBehind > margin || gapInFront > margin) return Verdict::Out;
    if (gapBehind < -margin && gapInFront < -margin) return Verdict::In;
    return Verdict::EitherWay;
}

// Checks `lists` against the ranges and depths, tile by tile; returns the
// number of entries expected (those that may go either way counted as in).
long checkLists(const TileLightLists& lists, const TileGrid& grid, const std::vector<LightSphere>& lights,
                const std::vector<TileRange>& ranges, const std::vector<DepthRange>& depths) {
    const int tileCount = grid.tileCount();
    CHECK(lists.grid.viewport == grid.viewport);
    CHECK(lists.grid.tileSize == grid.tileSize);
    REQUIRE(lists.offsets.size() == static_cast<std::size_t>(tileCount) + 1);
    REQUIRE(lists.offsets.front() == 0);
    REQUIRE(static_cast<std::size_t>(lists.offsets.back()) == lists.lights.size());
    int wrongTiles = 0;
    long entries = 0;
    for (int row = 0; row < grid.tiles().y; ++row)
        for (int column = 0; column < grid.tiles().x; ++column) {
            const int tile = grid.index({column, row});
            REQUIRE(lists.offsets[tile + 1] >= lists.offsets[tile]);
            const std::vector<int> got(lists.lights.begin() + lists.offsets[tile],
                                       lists.lights.begin() + lists.offsets[tile + 1]);
            std::vector<int> expected;   // those that must be in, and those that may
            std::vector<bool> optional;
            for (std::size_t i = 0; i < ranges.size(); ++i) {
                if (!rangeHolds(ranges[i], {column, row})) continue;
                const Verdict verdict = depthVerdict(lights[i], depths[static_cast<std::size_t>(tile)]);
                if (verdict == Verdict::Out) continue;
                expected.push_back(static_cast<int>(i));
                optional.push_back(verdict == Verdict::EitherWay);
            }
            entries += static_cast<long>(expected.size());
            // got must be expected, less some of the optional ones, in the same (increasing) order.
            bool same = true;
            std::size_t next = 0;
            for (std::size_t e = 0; e < expected.size() && same; ++e) {
                if (next < got.size() && got[next] == expected[e]) ++next;
                else if (!optional[e]) same = false;
            }
            same = same && next == got.size();
            if (!same && ++wrongTiles <= 5) {
                std::ostringstream text;
                text << "tile (" << column << ", " << row << "): lights";
                for (const int light : got) text << " " << light;
                text << "; expected";
                for (std::size_t e = 0; e < expected.size(); ++e) text << " " << expected[e] << (optional[e] ? "?" : "");
                FAIL_CHECK(text.str());
            }
        }
    CHECK(wrongTiles == 0);
    return entries;
}

} // namespace

TEST_CASE("Lab 08 (deferred): buildTileLightLists with every depth open lists, for every tile, the lights whose "
          "range holds it, in order",
          "[lab08][deferred]") {
    Random random(4096);
    for (const TestView& view : testViews()) {
        INFO(view.name);
        const glm::mat4 projection = view.projection();
        const std::vector<LightSphere> lights = randomLights(view, random, 150);
        std::vector<TileRange> ranges;
        for (const LightSphere& light : lights) ranges.push_back(stoa::lightTileRange(light, projection, view.near, view.grid));
        const std::vector<DepthRange> depths = openDepths(view.grid);
        const TileLightLists lists = stoa::buildTileLightLists(lights, projection, view.near, view.grid, depths);
        const long entries = checkLists(lists, view.grid, lights, ranges, depths);
        INFO(entries << " entries in all");
        CHECK(static_cast<long>(lists.lights.size()) == entries);
        CHECK(entries > view.grid.tileCount());   // the lights cover the picture several times over
    }
}

TEST_CASE("Lab 08 (deferred): buildTileLightLists keeps a light in a tile only where its sphere reaches the "
          "tile's depths, for random depths",
          "[lab08][deferred]") {
    Random random(5150);
    for (const TestView& view : testViews()) {
        INFO(view.name);
        const glm::mat4 projection = view.projection();
        const std::vector<LightSphere> lights = randomLights(view, random, 150);
        std::vector<TileRange> ranges;
        for (const LightSphere& light : lights) ranges.push_back(stoa::lightTileRange(light, projection, view.near, view.grid));
        // Each tile sees surfaces from some distance to a little or a lot farther; one in eight only sky.
        std::vector<DepthRange> depths(static_cast<std::size_t>(view.grid.tileCount()));
        for (DepthRange& range : depths) {
            if (random.chance(0.125f)) continue;   // the default DepthRange is empty
            range.nearest = view.near * std::exp(random.uniform(0.0f, 1.0f) * std::log(0.3 * view.far / view.near));
            range.farthest = range.nearest * random.uniform(1.0f, random.chance(0.5f) ? 1.2f : 4.0f);
        }
        const TileLightLists lists = stoa::buildTileLightLists(lights, projection, view.near, view.grid, depths);
        // How many the depths drop: the test means something only if it is many.
        long inRange = 0;
        for (int tile = 0; tile < view.grid.tileCount(); ++tile)
            for (const TileRange& range : ranges)
                if (rangeHolds(range, {tile % view.grid.tiles().x, tile / view.grid.tiles().x})) ++inRange;
        const long entries = checkLists(lists, view.grid, lights, ranges, depths);
        INFO(entries << " entries expected of " << inRange << " in the lights' ranges");
        CHECK(entries > 0);
        CHECK(entries < inRange * 3 / 4);
    }
}

TEST_CASE("Lab 08 (deferred): buildTileLightLists: a light nearer or farther than a tile's surfaces is kept when "
          "its reach gets to them",
          "[lab08][deferred]") {
    const TestView view = testViews()[0];   // 400x300, 16-pixel tiles
    const glm::mat4 projection = view.projection();
    // Lights on the view axis, all covering the middle tile (12, 9); their
    // distances straddle that tile's surfaces, 10 to 11 m away, in each way.
    const std::vector<LightSphere> lights{
        {{0.0f, 0.0f, -8.0f}, 2.5f},    // 0: in front, reaching 0.5 m into them: kept
        {{0.0f, 0.0f, -8.0f}, 1.5f},    // 1: in front, 0.5 m short: dropped
        {{0.0f, 0.0f, -13.0f}, 2.5f},   // 2: behind, reaching 0.5 m back into them: kept
        {{0.0f, 0.0f, -13.0f}, 1.5f},   // 3: behind, 0.5 m short: dropped
        {{0.0f, 0.0f, -10.5f}, 0.2f},   // 4: among them: kept
        {{0.0f, 0.0f, -10.5f}, 5.0f},   // 5: around them: kept
        {{0.0f, 0.0f, -0.5f}, 1.5f},    // 6: about the eye (every tile), 1 .. 2 m from the sky's empty range: dropped
    };
    std::vector<DepthRange> depths(static_cast<std::size_t>(view.grid.tileCount()));   // sky everywhere...
    const int middle = view.grid.index({12, 9});
    depths[static_cast<std::size_t>(middle)].nearest = 10.0f;   // ...but the middle tile
    depths[static_cast<std::size_t>(middle)].farthest = 11.0f;
    for (const LightSphere& light : lights)
        REQUIRE(rangeHolds(stoa::lightTileRange(light, projection, view.near, view.grid), {12, 9}));

    const TileLightLists lists = stoa::buildTileLightLists(lights, projection, view.near, view.grid, depths);
    REQUIRE(lists.offsets.size() == static_cast<std::size_t>(view.grid.tileCount()) + 1);
    const std::vector<int> got(lists.lights.begin() + lists.offsets[middle],
                               lists.lights.begin() + lists.offsets[middle + 1]);
    CHECK(got == std::vector<int>{0, 2, 4, 5});
    // The sky's tiles (DepthRange's default: empty) list nothing, not even the light about the eye.
    CHECK(lists.lights.size() == got.size());
}

TEST_CASE("Lab 08 (deferred): buildTileLightLists of no lights is an empty list per tile", "[lab08][deferred]") {
    const TestView view = testViews()[0];
    const TileLightLists lists =
        stoa::buildTileLightLists({}, view.projection(), view.near, view.grid, openDepths(view.grid));
    CHECK(lists.offsets == std::vector<int>(static_cast<std::size_t>(view.grid.tileCount()) + 1, 0));
    CHECK(lists.lights.empty());
}
