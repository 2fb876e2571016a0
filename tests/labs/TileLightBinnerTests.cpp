// The framework's own tile lists (framework/src/render/TileLightBinner.hpp,
// what the editor and the showcase draw with) against lab 08's reference
// buildTileLightLists() (the solutions' tiled_lights.cpp, linked here): the
// same offsets and the same lights in the same order, entry for entry, so that
// every pixel's sum over its tile's lights is the same, bit for bit. Random
// scenes on several pictures and tile sizes, with random cameras (field of
// view, near plane), random tile depths and sky tiles, lights in front of the
// camera, behind it, exactly touching and crossing the near plane, covering
// the whole screen and off it; light counts either side of 64 (one word of the
// binner's bits). And the tiles' depth ranges against the per-pixel
// conversion the renderer made before (min and max of every pixel's distance).

#include "catch.hpp"
#include "TestRandom.hpp"
#include "TileDepthRanges.hpp"
#include "TileLightBinner.hpp"
#include "lab08.hpp"

#include <stoa/render/DeferredShading.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

using stoa::DepthRange;
using stoa::LightSphere;
using stoa::TileGrid;
using stoa::TileLightBinner;
using stoa::TileLightLists;

namespace {

using Random = stoa::test::Random;

struct Camera {
    float fovYDegrees, near, far;
    TileGrid grid;
    glm::mat4 projection() const {
        const float aspect = static_cast<float>(grid.viewport.x) / static_cast<float>(grid.viewport.y);
        return glm::perspective(glm::radians(fovYDegrees), aspect, near, far);
    }
};

Camera randomCamera(Random& random, glm::ivec2 viewport, int tileSize) {
    Camera camera{random.uniform(30.0f, 100.0f), random.uniform(0.05f, 1.0f), random.uniform(50.0f, 500.0f), {}};
    camera.grid.viewport = viewport;
    camera.grid.tileSize = tileSize;
    return camera;
}

// One light of each kind the reference treats apart, then random ones.
LightSphere randomLight(Random& random, const Camera& camera, int kind) {
    LightSphere light;
    light.reach = random.uniform(0.2f, 6.0f);
    switch (kind % 8) {
    case 0:   // behind the camera
        light.centerView = random.inBox({-10.0f, -10.0f, camera.near + light.reach}, {10.0f, 10.0f, 20.0f});
        break;
    case 1:   // its far side exactly on the near plane: nothing of it past it
        light.centerView = random.inBox({-3.0f, -3.0f, 0.0f}, {3.0f, 3.0f, 0.0f});
        light.centerView.z = -camera.near + light.reach;
        break;
    case 2:   // its near side exactly on the near plane, or just through it
        light.centerView = random.inBox({-3.0f, -3.0f, 0.0f}, {3.0f, 3.0f, 0.0f});
        light.centerView.z = -camera.near - light.reach + (random.chance(0.5f) ? 0.0f : 1e-3f);
        break;
    case 3:   // across the near plane
        light.centerView = random.inBox({-5.0f, -5.0f, -camera.near - 1.0f}, {5.0f, 5.0f, -camera.near + 1.0f});
        break;
    case 4:   // covering the whole screen: large and close in front
        light.reach = random.uniform(20.0f, 60.0f);
        light.centerView = {random.uniform(-1.0f, 1.0f), random.uniform(-1.0f, 1.0f),
                            -camera.near - light.reach - random.uniform(0.01f, 2.0f)};
        break;
    case 5:   // off the screen, to a side, far beyond the frustum
        light.centerView = {random.chance(0.5f) ? -200.0f : 200.0f, random.uniform(-200.0f, 200.0f),
                            -random.uniform(5.0f, 60.0f)};
        break;
    default:  // in front, near the view, some partly off the edges
        light.centerView = random.inBox({-40.0f, -25.0f, -80.0f}, {40.0f, 25.0f, -camera.near});
        break;
    }
    return light;
}

// Random depths: sky, thin slabs and deep tiles.
std::vector<DepthRange> randomDepths(Random& random, const TileGrid& grid) {
    std::vector<DepthRange> depths(static_cast<std::size_t>(grid.tileCount()));
    for (DepthRange& range : depths) {
        if (random.chance(0.15f)) continue;   // sky: the empty range
        range.nearest = random.uniform(0.1f, 70.0f);
        range.farthest = range.nearest + (random.chance(0.3f) ? 0.0f : random.uniform(0.0f, 40.0f));
    }
    return depths;
}

void requireSameLists(const TileLightLists& reference, const TileLightLists& fast, const std::string& scene) {
    INFO(scene);
    REQUIRE(fast.grid.viewport == reference.grid.viewport);
    REQUIRE(fast.grid.tileSize == reference.grid.tileSize);
    REQUIRE(fast.offsets == reference.offsets);
    REQUIRE(fast.lights == reference.lights);
}

} // namespace

TEST_CASE("TileLightBinner (the editor's and showcase's tile lists) gives lab 08's reference lists, entry for entry, "
          "on random scenes",
          "[lab08][deferred][binner]") {
    struct Picture {
        glm::ivec2 viewport;
        int tileSize;
    };
    const std::vector<Picture> pictures = {
        {{1280, 720}, 16}, {{1920, 1080}, 16}, {{400, 300}, 16}, {{100, 70}, 8}, {{257, 129}, 32}, {{90, 200}, 8}};
    const std::vector<int> lightCounts = {0, 1, 63, 64, 65, 302, 700};
    Random random(27);
    TileLightBinner binner;   // one for every scene, as a renderer keeps it: its buffers are reused
    TileLightLists fast;
    long entries = 0, scenes = 0;
    for (const Picture& picture : pictures)
        for (const int count : lightCounts)
            for (int repeat = 0; repeat < 2; ++repeat) {
                const Camera camera = randomCamera(random, picture.viewport, picture.tileSize);
                std::vector<LightSphere> lights;
                for (int i = 0; i < count; ++i) lights.push_back(randomLight(random, camera, random.below(8)));
                const std::vector<DepthRange> depths = randomDepths(random, camera.grid);
                const glm::mat4 projection = camera.projection();
                const TileLightLists reference =
                    stoa::buildTileLightLists(lights, projection, camera.near, camera.grid, depths);
                binner.assign(lights, projection, camera.near, camera.grid, depths, fast);
                requireSameLists(reference, fast,
                                 std::to_string(picture.viewport.x) + "x" + std::to_string(picture.viewport.y) + ", " +
                                     std::to_string(picture.tileSize) + "-pixel tiles, " + std::to_string(count) +
                                     " lights, repeat " + std::to_string(repeat));
                entries += static_cast<long>(reference.lights.size());
                ++scenes;
            }
    CHECK(scenes == 84);
    CHECK(entries > 100000);   // the comparisons saw full lists, not empty ones
}

TEST_CASE("TileLightBinner: every depth open (no tile sky), a light covering the whole screen and one on every tile "
          "edge list the same as lab 08's reference",
          "[lab08][deferred][binner]") {
    Random random(8);
    const Camera camera{60.0f, 0.1f, 100.0f, TileGrid{{640, 360}, 16}};
    const glm::mat4 projection = camera.projection();
    std::vector<LightSphere> lights;
    lights.push_back({{0.0f, 0.0f, -30.0f}, 100.0f});   // crosses the near plane: every tile
    lights.push_back({{0.0f, 0.0f, -5.2f}, 5.0f});      // in front, larger than the view
    for (int i = 0; i < 200; ++i) lights.push_back(randomLight(random, camera, 6));
    std::vector<DepthRange> depths(static_cast<std::size_t>(camera.grid.tileCount()), DepthRange{0.0f, 1e9f});
    TileLightBinner binner;
    TileLightLists fast;
    binner.assign(lights, projection, camera.near, camera.grid, depths, fast);
    requireSameLists(stoa::buildTileLightLists(lights, projection, camera.near, camera.grid, depths), fast, "open depths");
    for (int t = 0; t < camera.grid.tileCount(); ++t) {
        REQUIRE(fast.offsets[static_cast<std::size_t>(t) + 1] > fast.offsets[static_cast<std::size_t>(t)]);
        REQUIRE(fast.lights[static_cast<std::size_t>(fast.offsets[static_cast<std::size_t>(t)])] == 0);
    }
}

TEST_CASE("TileDepthRanges::compute equals the per-pixel distances' minimum and maximum of every tile, sky left out",
          "[deferred][binner]") {
    Random random(5);
    for (const glm::ivec2 size : {glm::ivec2(1280, 720), glm::ivec2(100, 70), glm::ivec2(33, 17)}) {
        const Camera camera = randomCamera(random, size, 16);
        const glm::mat4 projection = camera.projection();
        // A depth buffer of ramps, noise and sky, as the G-buffer's 24 bits give them.
        std::vector<float> depth(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y));
        for (std::size_t i = 0; i < depth.size(); ++i) {
            const float value = random.chance(0.1f) ? 1.0f : random.uniform(0.0f, 1.0f);
            depth[i] = static_cast<float>(static_cast<double>(static_cast<std::uint32_t>(value * 16777215.0f)) / 16777215.0);
        }
        // Sky over a whole tile as well.
        for (int y = 0; y < std::min(16, size.y); ++y)
            for (int x = 0; x < std::min(16, size.x); ++x) depth[static_cast<std::size_t>(y * size.x + x)] = 1.0f;
        std::vector<DepthRange> expected(static_cast<std::size_t>(camera.grid.tileCount()));
        const float a = projection[2][2], b = projection[3][2];
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const float d = depth[static_cast<std::size_t>(y * size.x + x)];
                if (d >= 1.0f) continue;
                const float distance = b / (2.0f * d - 1.0f + a);
                DepthRange& range = expected[static_cast<std::size_t>(camera.grid.index({x / 16, y / 16}))];
                if (range.empty()) {
                    range.nearest = range.farthest = distance;
                } else {
                    range.nearest = std::min(range.nearest, distance);
                    range.farthest = std::max(range.farthest, distance);
                }
            }
        stoa::TileDepthRanges tileDepths;
        const std::vector<DepthRange>& ranges = tileDepths.compute(depth.data(), size, projection, camera.grid);
        REQUIRE(ranges.size() == expected.size());
        CHECK(ranges[0].empty());
        for (std::size_t t = 0; t < ranges.size(); ++t) {
            INFO("tile " << t << " of " << size.x << "x" << size.y);
            REQUIRE(ranges[t].empty() == expected[t].empty());
            if (expected[t].empty()) continue;
            REQUIRE(std::memcmp(&ranges[t].nearest, &expected[t].nearest, sizeof(float)) == 0);
            REQUIRE(std::memcmp(&ranges[t].farthest, &expected[t].farthest, sizeof(float)) == 0);
        }
    }
}
