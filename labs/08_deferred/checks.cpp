// Lab 08's property checks; see checks.hpp. They call your lightReach(),
// lightTileRange() and buildTileLightLists() on data of their own and test what
// the page states of them. The tile checks use a camera of their own on a small
// picture, with lights placed where the graded scenes never put one: at every
// edge of the picture, half off it, just past the near plane.

#include "checks.hpp"
#include "lab08.hpp"

#include <stoa/render/DeferredShading.hpp>
#include <stoa/scene/Light.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lab08 {

namespace {

std::string number(float value) { return stoa::checkNumber(value, 4); }

std::string tileName(glm::ivec2 tile) { return "(" + std::to_string(tile.x) + ", " + std::to_string(tile.y) + ")"; }

std::string describe(const stoa::LightSphere& light) {
    return "the light at " + stoa::checkVector(light.centerView) + " (view space) of reach " + number(light.reach);
}

bool holds(const stoa::TileRange& range, glm::ivec2 tile) {
    return tile.x >= range.first.x && tile.x <= range.last.x && tile.y >= range.first.y && tile.y <= range.last.y;
}

// The small picture the tile checks use: 400 x 270 pixels in tiles of 32, so
// the last column and row are partly outside it.
struct TileScene {
    stoa::TileGrid grid;
    glm::mat4 projection;
    float near = 0.5f;
    explicit TileScene(glm::ivec2 viewport = glm::ivec2(400, 270)) {
        grid.viewport = viewport;
        grid.tileSize = 32;
        projection = glm::perspective(glm::radians(60.0f), float(viewport.x) / float(viewport.y), near, 80.0f);
    }
};

// Lights whose spheres lie wholly beyond the near plane, their centres anywhere
// from well inside the picture to a little past each edge.
std::vector<stoa::LightSphere> lightsAround(const TileScene& scene, stoa::CheckRandom& random, int count) {
    std::vector<stoa::LightSphere> lights;
    const glm::mat4 back = glm::inverse(scene.projection);
    while (static_cast<int>(lights.size()) < count) {
        stoa::LightSphere light;
        const float distance = random.between(1.0f, 30.0f);
        const glm::vec4 direction = back * glm::vec4(random.between(-1.4f, 1.4f), random.between(-1.4f, 1.4f), 0.0f, 1.0f);
        light.centerView = glm::normalize(glm::vec3(direction) / direction.w) * distance;
        light.reach = random.between(0.05f, 0.6f) * distance;
        if (light.centerView.z + light.reach < -scene.near) lights.push_back(light);
    }
    return lights;
}

// The view-space point at `depth` in front of the camera that lands on `pixel`.
glm::vec3 pointOnPixel(const TileScene& scene, glm::vec2 pixel, float depth) {
    const glm::vec2 ndc = pixel / glm::vec2(scene.grid.viewport) * 2.0f - 1.0f;
    const glm::vec4 back = glm::inverse(scene.projection) * glm::vec4(ndc, 0.0f, 1.0f);
    const glm::vec3 point = glm::vec3(back) / back.w;
    return point * (depth / -point.z);
}

// Tiny lights whose leftmost (or lowest) point lands 0.3 pixels before a tile's
// edge, in the last pixel of the tile before it: a range must start at that tile.
std::vector<stoa::LightSphere> lightsAtTileEdges(const TileScene& scene, stoa::CheckRandom& random) {
    std::vector<stoa::LightSphere> lights;
    const glm::vec2 size(scene.grid.viewport);
    for (int axis = 0; axis < 2; ++axis) {
        for (int edge = scene.grid.tileSize; edge < scene.grid.viewport[axis]; edge += scene.grid.tileSize) {
            glm::vec2 pixel;
            pixel[axis] = static_cast<float>(edge) - 0.3f;
            pixel[1 - axis] = random.between(10.0f, size[1 - axis] - 10.0f);
            const float depth = random.between(4.0f, 30.0f);
            stoa::LightSphere light;
            light.reach = 0.001f * depth;
            light.centerView = pointOnPixel(scene, pixel, depth);
            light.centerView[axis] += light.reach;
            lights.push_back(light);
        }
    }
    return lights;
}

// Lights whose box (C + (+-R, +-R, +-R)) lies wholly beyond one side of the view,
// a little past its edge: on no tile.
std::vector<std::pair<stoa::LightSphere, const char*>> lightsOffThePicture(const TileScene& scene,
                                                                         stoa::CheckRandom& random) {
    std::vector<std::pair<stoa::LightSphere, const char*>> lights;
    const glm::vec2 size(scene.grid.viewport);
    const float tanY = std::tan(glm::radians(30.0f)), tanX = tanY * size.x / size.y;
    const char* sides[] = {"right of", "above", "left of", "below"};
    for (int i = 0; i < 40; ++i) {
        const int side = i % 4, axis = side % 2;
        const float sign = side < 2 ? 1.0f : -1.0f;
        glm::vec2 ndc;
        ndc[axis] = sign * random.between(1.05f, 1.9f);
        ndc[1 - axis] = random.between(-1.2f, 1.2f);
        const float depth = random.between(3.0f, 30.0f);
        const glm::vec3 center = pointOnPixel(scene, (ndc * 0.5f + 0.5f) * size, depth);
        // How far beyond the side's plane (through the eye) the centre lies, in
        // the units a box's corner offsets (+-R on both axes) move it by.
        const float slope = axis == 0 ? tanX : tanY;
        const float beyond = (sign * center[axis] - depth * slope) / (1.0f + slope);
        stoa::LightSphere light;
        light.centerView = center;
        light.reach = random.between(0.1f, 0.95f) * std::min(beyond, depth - scene.near);
        lights.emplace_back(light, sides[side]);
    }
    return lights;
}

} // namespace

stoa::CheckResult checkReachSolvesTheFalloff() {
    struct Row {
        glm::vec3 color, attenuation;
        const char* kind;
    };
    const Row rows[] = {
        {{1.0f, 0.6f, 0.2f}, {1.0f, 1.0f, 5.0f}, "quadratic (the wandering lights')"},
        {{0.3f, 1.6f, 0.9f}, {1.0f, 0.09f, 0.032f}, "quadratic, weak"},
        {{2.0f, 2.0f, 2.0f}, {0.5f, 0.0f, 0.8f}, "quadratic, no linear term"},
        {{1.2f, 0.4f, 0.4f}, {1.0f, 0.5f, 0.0f}, "linear only (q = 0)"},
        {{0.7f, 0.9f, 0.2f}, {1.0f, 2.0f, 0.0f}, "linear only (q = 0)"},
        {{0.01f, 0.01f, 0.01f}, {1.0f, 1.0f, 1.0f}, "too dim to reach the cut-off"},
    };
    const float cutoff = 1.0f / 64.0f;
    for (const Row& row : rows) {
        stoa::PointLight light;
        light.color = row.color;
        light.attenuation = row.attenuation;
        const float reach = stoa::lightReach(light, cutoff);
        const std::string what = "lightReach() of a light " + std::string(row.kind) + " with (c, l, q) = " +
                                 stoa::checkVector(row.attenuation) + " and colour " + stoa::checkVector(row.color);
        const float peak = std::max({row.color.r, row.color.g, row.color.b});
        if (peak / row.attenuation.x <= cutoff) {
            if (reach != 0.0f)
                return stoa::CheckResult::fail(what + " is " + number(reach) +
                                               "; it is never brighter than the cut-off (k >= 0): its reach is 0 "
                                               "(docs: How far a light reaches)");
            continue;
        }
        const float c = row.attenuation.x, l = row.attenuation.y, q = row.attenuation.z;
        const float atReach = peak / (c + l * reach + q * reach * reach);
        if (!std::isfinite(reach) || reach <= 0.0f || std::fabs(atReach - cutoff) > 1e-3f * cutoff)
            return stoa::CheckResult::fail(what + " is " + number(reach) + " m; there the brightest channel is " +
                                           number(atReach) + ", not the cut-off " + number(cutoff) +
                                           ". With q = 0 the equation is a line: R = -k / l "
                                           "(docs: How far a light reaches)");
    }
    stoa::PointLight steady;
    steady.attenuation = glm::vec3(1.0f, 0.0f, 0.0f);
    const float everywhere = stoa::lightReach(steady, cutoff);
    if (!(everywhere >= 1e6f) || !std::isfinite(everywhere))
        return stoa::CheckResult::fail("lightReach() of a light with (c, l, q) = (1, 0, 0), which never falls off, is " +
                                       number(everywhere) + "; it reaches everything: return a very large, finite "
                                       "distance (the light's volume is a sphere of that radius: an infinite one "
                                       "makes its vertices infinite or NaN) (docs: How far a light reaches)");
    return stoa::CheckResult::pass("lightReach() meets the cut-off for quadratic and linear lights, is 0 for a light "
                                   "too dim and very large for one that never falls off (7 lights)");
}

namespace {

// Points on and in each sphere (its four points furthest left, right, down and
// up first; 200 more for the first `spread` lights): the first whose tile
// lightTileRange() leaves out, as a failure message. `landed` counts the points
// that land on the picture.
std::optional<std::string> firstMissedTile(const TileScene& scene, const std::vector<stoa::LightSphere>& lights,
                                           int spread, stoa::CheckRandom& random, int& landed) {
    const glm::ivec2 tiles = scene.grid.tiles();
    const glm::ivec2 size = scene.grid.viewport;
    for (int n = 0; n < static_cast<int>(lights.size()); ++n) {
        const stoa::LightSphere& light = lights[static_cast<std::size_t>(n)];
        const stoa::TileRange range = stoa::lightTileRange(light, scene.projection, scene.near, scene.grid);
        // Points on the sphere and inside it, its four points furthest left, right,
        // down and up first: every tile one lands in must be in the range.
        const glm::vec3 extremes[] = {{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
        for (int i = 0; i < (n < spread ? 204 : 4); ++i) {
            const glm::vec3 direction = i < 4 ? extremes[i]
                                              : glm::vec3(random.between(-1.0f, 1.0f), random.between(-1.0f, 1.0f),
                                                          random.between(-1.0f, 1.0f));
            if (glm::length(direction) < 1e-3f) continue;
            const float scale = i < 4 || i % 2 == 0 ? 0.999f : random.next();
            const glm::vec3 point = light.centerView + glm::normalize(direction) * light.reach * scale;
            const glm::vec4 clip = scene.projection * glm::vec4(point, 1.0f);
            const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(scene.grid.viewport);
            if (pixel.x < 0.0f || pixel.y < 0.0f || pixel.x >= scene.grid.viewport.x || pixel.y >= scene.grid.viewport.y)
                continue;   // off the picture
            const glm::ivec2 tile = glm::ivec2(glm::floor(pixel)) / scene.grid.tileSize;
            ++landed;
            if (!holds(range, tile))
                return "lightTileRange() of " + describe(light) + " is columns " + std::to_string(range.first.x) + " to " +
                    std::to_string(range.last.x) + ", rows " + std::to_string(range.first.y) + " to " +
                    std::to_string(range.last.y) + ", but a point of its sphere lands in pixel (" +
                    number(pixel.x) + ", " + number(pixel.y) + "), tile " + tileName(tile) + " of " +
                    tileName(tiles) + " on a " + std::to_string(size.x) + " x " + std::to_string(size.y) +
                    " picture in tiles of 32. The range must hold every tile the "
                    "sphere covers, at every edge of the picture (docs: Which tiles a light touches)";
        }
    }
    return std::nullopt;
}

} // namespace

stoa::CheckResult checkTileRangesHoldTheSphere() {
    const TileScene scene;
    const glm::ivec2 tiles = scene.grid.tiles();
    stoa::CheckRandom random(20261129u);
    int landed = 0;
    std::vector<stoa::LightSphere> lights = lightsAround(scene, random, 300);
    const int spread = static_cast<int>(lights.size());
    for (const stoa::LightSphere& light : lightsAtTileEdges(scene, random)) lights.push_back(light);
    if (std::optional<std::string> missed = firstMissedTile(scene, lights, spread, random, landed))
        return stoa::CheckResult::fail(*missed);
    for (const auto& [light, side] : lightsOffThePicture(scene, random)) {
        const stoa::TileRange range = stoa::lightTileRange(light, scene.projection, scene.near, scene.grid);
        if (!range.empty())
            return stoa::CheckResult::fail(
                "lightTileRange() of " + describe(light) + " is columns " + std::to_string(range.first.x) + " to " +
                std::to_string(range.last.x) + ", rows " + std::to_string(range.first.y) + " to " +
                std::to_string(range.last.y) + ", but the box around its sphere lies wholly " + side +
                " the picture: its rectangle lies outside [-1, 1] on that axis, and the range is empty "
                "(docs: Which tiles a light touches)");
    }
    // Spheres that cross the near plane, their centres a little before or behind
    // it and off to the sides: part of each lies behind the eye, where nothing
    // can be projected, so the range is every tile.
    for (int i = 0; i < 20; ++i) {
        stoa::LightSphere light;
        light.reach = random.between(0.3f, 3.0f);
        light.centerView = glm::vec3(random.between(-2.0f, 2.0f), random.between(-2.0f, 2.0f),
                                     -scene.near + random.between(-0.9f, 0.9f) * light.reach);
        const stoa::TileRange range = stoa::lightTileRange(light, scene.projection, scene.near, scene.grid);
        if (range.empty() || range.first != glm::ivec2(0) || range.last != tiles - 1)
            return stoa::CheckResult::fail(
                "lightTileRange() of " + describe(light) + " is " +
                (range.empty() ? std::string("empty")
                               : "columns " + std::to_string(range.first.x) + " to " + std::to_string(range.last.x) +
                                     ", rows " + std::to_string(range.first.y) + " to " + std::to_string(range.last.y)) +
                ", but the sphere crosses the near plane (z = -0.5): part of it lies behind the eye, where its corners "
                "cannot be projected, so the range is every tile, columns 0 to " + std::to_string(tiles.x - 1) +
                ", rows 0 to " + std::to_string(tiles.y - 1) + " (docs: Which tiles a light touches)");
    }
    // A picture whose last column and row of tiles are one pixel wide (384 and 256
    // are whole tiles): the last pixel, viewport - 1, starts a tile of its own.
    const TileScene thin(glm::ivec2(385, 257));
    const std::vector<stoa::LightSphere> edgeLights = lightsAround(thin, random, 150);
    if (std::optional<std::string> missed = firstMissedTile(thin, edgeLights, 150, random, landed))
        return stoa::CheckResult::fail(*missed);
    return stoa::CheckResult::pass("lightTileRange() holds the tile of every one of " + std::to_string(landed) +
                                   " points of " + std::to_string(lights.size() + edgeLights.size()) +
                                   " spheres in and around two pictures (tiny ones at the tiles' edges; one picture "
                                   "whose last tiles are a pixel wide), is empty for 40 lights wholly off it and "
                                   "whole for 20 that cross the near plane");
}

stoa::CheckResult checkTileListsMatchTheRanges() {
    const TileScene scene;
    stoa::CheckRandom random(20261129u);
    std::vector<stoa::LightSphere> lights = lightsAround(scene, random, 60);
    std::vector<stoa::DepthRange> depths(static_cast<std::size_t>(scene.grid.tileCount()));
    for (stoa::DepthRange& range : depths) {
        if (random.next() < 0.15f) continue;   // sky: empty
        range.nearest = random.between(1.0f, 25.0f);
        range.farthest = range.nearest + random.between(0.0f, 10.0f);
    }
    // Light 0 around the camera (its range is every tile), and a last tile that it
    // reaches: the last tile's list is written too, and every list that has light
    // 0 starts with it.
    stoa::LightSphere around;
    around.centerView = glm::vec3(0.3f, -0.2f, -0.4f);
    around.reach = 4.0f;
    lights.insert(lights.begin(), around);
    depths.back().nearest = 2.0f;
    depths.back().farthest = 3.0f;
    const stoa::TileLightLists lists = stoa::buildTileLightLists(lights, scene.projection, scene.near, scene.grid, depths);
    const int tileCount = scene.grid.tileCount();
    if (lists.grid.viewport != scene.grid.viewport || lists.grid.tileSize != scene.grid.tileSize)
        return stoa::CheckResult::fail("buildTileLightLists() gave lists whose grid is " +
                                       std::to_string(lists.grid.viewport.x) + " x " +
                                       std::to_string(lists.grid.viewport.y) + " pixels in tiles of " +
                                       std::to_string(lists.grid.tileSize) + "; they were built for " +
                                       std::to_string(scene.grid.viewport.x) + " x " +
                                       std::to_string(scene.grid.viewport.y) + " in tiles of " +
                                       std::to_string(scene.grid.tileSize) +
                                       ": lists.grid is the grid given (docs: Building the lists)");
    if (lists.offsets.size() != static_cast<std::size_t>(tileCount) + 1 || lists.offsets.front() != 0 ||
        static_cast<std::size_t>(lists.offsets.back()) != lists.lights.size())
        return stoa::CheckResult::fail("buildTileLightLists() gave " + std::to_string(lists.offsets.size()) +
                                       " offsets for " + std::to_string(tileCount) +
                                       " tiles; expected tileCount + 1, the first 0 and the last the length of the "
                                       "lists (docs: Building the lists)");
    std::vector<stoa::TileRange> ranges;
    for (const stoa::LightSphere& light : lights)
        ranges.push_back(stoa::lightTileRange(light, scene.projection, scene.near, scene.grid));
    const glm::ivec2 tiles = scene.grid.tiles();
    for (int row = 0; row < tiles.y; ++row) {
        for (int col = 0; col < tiles.x; ++col) {
            const int tile = scene.grid.index({col, row});
            const stoa::DepthRange& range = depths[static_cast<std::size_t>(tile)];
            std::vector<int> expected;
            for (std::size_t i = 0; i < lights.size(); ++i) {
                const float distance = -lights[i].centerView.z;
                const bool meets = !range.empty() && distance - lights[i].reach <= range.farthest &&
                                   distance + lights[i].reach >= range.nearest;
                if (holds(ranges[i], {col, row}) && meets) expected.push_back(static_cast<int>(i));
            }
            const int begin = lists.offsets[static_cast<std::size_t>(tile)];
            const int end = lists.offsets[static_cast<std::size_t>(tile) + 1];
            const std::vector<int> listed(lists.lights.begin() + begin, lists.lights.begin() + std::max(begin, end));
            if (listed != expected) {
                std::string names;
                for (const int i : listed) names += (names.empty() ? "" : " ") + std::to_string(i);
                std::string wanted;
                for (const int i : expected) wanted += (wanted.empty() ? "" : " ") + std::to_string(i);
                return stoa::CheckResult::fail(
                    "buildTileLightLists(): tile " + tileName({col, row}) + " lists lights [" + names +
                    "]; the lights whose lightTileRange() holds it and whose depths meet the tile's are [" + wanted +
                    "], in increasing order, each once (docs: Building the lists, Depth bounds)");
            }
        }
    }
    return stoa::CheckResult::pass("buildTileLightLists() lists exactly the right lights, in order, in each of " +
                                   std::to_string(tileCount) + " tiles (" + std::to_string(lights.size()) + " lights, " +
                                   std::to_string(lists.lights.size()) + " entries)");
}

} // namespace lab08
