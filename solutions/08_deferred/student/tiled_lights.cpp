// Lab 08, part 3: tiled light culling on the CPU. Read docs/labs/08_deferred.md,
// "Tiled shading". The app cuts the picture into square tiles, asks
// buildTileLightLists() which lights can reach each one, and hands the lists
// to one full-screen pass (shaders/deferred/tiled.frag), where each pixel
// loops over its own tile's lights only.

#include "lab08.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/render/DeferredShading.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace stoa {

TileRange lightTileRange(const LightSphere& light, const glm::mat4& projection, float near, const TileGrid& grid) {
    const glm::vec3& c = light.centerView;
    const float r = light.reach;
    const glm::ivec2 tiles = grid.tiles();
    // The sphere spans view depths c.z - r .. c.z + r; what the camera sees lies at z <= -near.
    if (c.z - r > -near) return TileRange{};                 // wholly between the eye and the near plane, or behind
    if (c.z + r > -near) return {glm::ivec2(0), tiles - 1};  // crosses the near plane: any tile
    glm::vec2 lower(1e30f), upper(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 offset((corner & 1) ? r : -r, (corner & 2) ? r : -r, (corner & 4) ? r : -r);
        const glm::vec4 clip = projection * glm::vec4(c + offset, 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        lower = glm::min(lower, ndc);
        upper = glm::max(upper, ndc);
    }
    if (upper.x < -1.0f || upper.y < -1.0f || lower.x > 1.0f || lower.y > 1.0f) return TileRange{};
    lower = glm::clamp(lower, -1.0f, 1.0f);
    upper = glm::clamp(upper, -1.0f, 1.0f);
    // [-1, 1] to pixels, then to tiles; the last pixel of the picture is viewport - 1.
    const glm::vec2 viewport(grid.viewport);
    const glm::vec2 firstPixel = (lower * 0.5f + 0.5f) * viewport;
    const glm::vec2 lastPixel = glm::min((upper * 0.5f + 0.5f) * viewport, viewport - 1.0f);
    TileRange range;
    range.first = glm::clamp(glm::ivec2(glm::floor(firstPixel)) / grid.tileSize, glm::ivec2(0), tiles - 1);
    range.last = glm::clamp(glm::ivec2(glm::floor(lastPixel)) / grid.tileSize, glm::ivec2(0), tiles - 1);
    return range;
}

// True when the light's sphere reaches into the depths the tile sees.
bool reachesDepths(const LightSphere& light, const DepthRange& depths) {
    const float distance = -light.centerView.z;
    return !depths.empty() && distance - light.reach <= depths.farthest && distance + light.reach >= depths.nearest;
}

TileLightLists buildTileLightLists(const std::vector<LightSphere>& lights, const glm::mat4& projection, float near,
                                   const TileGrid& grid, const std::vector<DepthRange>& tileDepths) {
    TileLightLists lists;
    lists.grid = grid;
    const int tileCount = grid.tileCount();
    std::vector<TileRange> ranges;
    ranges.reserve(lights.size());
    std::vector<int> counts(static_cast<std::size_t>(tileCount), 0);
    for (const LightSphere& light : lights) {
        const TileRange range = lightTileRange(light, projection, near, grid);
        ranges.push_back(range);
        if (range.empty()) continue;
        for (int y = range.first.y; y <= range.last.y; ++y)
            for (int x = range.first.x; x <= range.last.x; ++x) {
                const int tile = grid.index({x, y});
                if (reachesDepths(light, tileDepths[static_cast<std::size_t>(tile)])) ++counts[static_cast<std::size_t>(tile)];
            }
    }
    lists.offsets.assign(static_cast<std::size_t>(tileCount) + 1, 0);
    for (int t = 0; t < tileCount; ++t) lists.offsets[t + 1] = lists.offsets[t] + counts[t];
    lists.lights.resize(static_cast<std::size_t>(lists.offsets.back()));
    std::vector<int> next(lists.offsets.begin(), lists.offsets.end() - 1);
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        const TileRange& range = ranges[i];
        if (range.empty()) continue;
        for (int y = range.first.y; y <= range.last.y; ++y)
            for (int x = range.first.x; x <= range.last.x; ++x) {
                const int tile = grid.index({x, y});
                if (reachesDepths(lights[i], tileDepths[static_cast<std::size_t>(tile)]))
                    lists.lights[static_cast<std::size_t>(next[static_cast<std::size_t>(tile)]++)] = static_cast<int>(i);
            }
    }
    return lists;
}

} // namespace stoa
