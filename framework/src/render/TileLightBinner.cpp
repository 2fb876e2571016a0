#include "TileLightBinner.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace stoa {

namespace {

constexpr int kBitsPerWord = 64;

// Window depth d in [0, 1) -> distance in front of the camera. With the
// normalised depth n = 2 d - 1, z_view = -P[3][2] / (n + P[2][2]). Each
// operation is rounded monotonically and the result grows with d, so the
// distance of a tile's smallest (largest) depth is its smallest (largest)
// distance, bit for bit.
float distanceOf(float windowDepth, float p22, float p32) { return p32 / (2.0f * windowDepth - 1.0f + p22); }

} // namespace

const std::vector<DepthRange>& TileLightBinner::depthRanges(const float* windowDepth, glm::ivec2 size,
                                                            const glm::mat4& projection, const TileGrid& grid) {
    const glm::ivec2 tiles = grid.tiles();
    const std::size_t tileCount = static_cast<std::size_t>(grid.tileCount());
    // Sky (1) is left out: as 2 for the smallest depth, as -1 for the largest.
    m_lowest.assign(tileCount, 2.0f);
    m_highest.assign(tileCount, -1.0f);
    for (int y = 0; y < size.y; ++y) {
        const float* row = windowDepth + static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x);
        float* lowest = m_lowest.data() + static_cast<std::size_t>(y / grid.tileSize) * static_cast<std::size_t>(tiles.x);
        float* highest = m_highest.data() + (lowest - m_lowest.data());
        for (int column = 0; column < tiles.x; ++column) {
            const int begin = column * grid.tileSize;
            const int end = std::min(begin + grid.tileSize, size.x);
            float low = lowest[column], high = highest[column];
            for (int x = begin; x < end; ++x) {
                const float d = row[x];
                const bool sky = d >= 1.0f;
                low = std::min(low, sky ? 2.0f : d);
                high = std::max(high, sky ? -1.0f : d);
            }
            lowest[column] = low;
            highest[column] = high;
        }
    }
    const float p22 = projection[2][2], p32 = projection[3][2];
    m_ranges.assign(tileCount, DepthRange{});
    for (std::size_t t = 0; t < tileCount; ++t) {
        if (m_lowest[t] > 1.0f) continue;   // every pixel sky: the empty range
        m_ranges[t].nearest = distanceOf(m_lowest[t], p22, p32);
        m_ranges[t].farthest = distanceOf(m_highest[t], p22, p32);
    }
    return m_ranges;
}

TileLightBinner::Footprint TileLightBinner::footprint(const LightSphere& sphere, const glm::mat4& projection, float near,
                                                      const TileGrid& grid) const {
    Footprint light;
    const glm::vec3 centre = sphere.centerView;
    const float reach = sphere.reach;
    light.nearest = -centre.z - reach;
    light.farthest = -centre.z + reach;
    const glm::ivec2 tiles = grid.tiles();
    if (centre.z - reach > -near) return light;   // nothing of it past the near plane: no tile
    if (centre.z + reach > -near) {              // through the near plane: it may cover any tile
        light.columnFirst = light.rowFirst = 0;
        light.columnLast = tiles.x - 1;
        light.rowLast = tiles.y - 1;
        return light;
    }
    // The rectangle that the eight corners of the box around the sphere span
    // on the screen, in normalised device coordinates.
    const float xs[2] = {centre.x - reach, centre.x + reach};
    const float ys[2] = {centre.y - reach, centre.y + reach};
    const float zs[2] = {centre.z - reach, centre.z + reach};
    float left = 1e30f, bottom = 1e30f, right = -1e30f, top = -1e30f;
    for (const float z : zs)
        for (const float y : ys)
            for (const float x : xs) {
                const glm::vec4 cornerClip = projection * glm::vec4(x, y, z, 1.0f);
                const float cornerX = cornerClip.x / cornerClip.w, cornerY = cornerClip.y / cornerClip.w;
                left = std::min(left, cornerX);
                right = std::max(right, cornerX);
                bottom = std::min(bottom, cornerY);
                top = std::max(top, cornerY);
            }
    if (right < -1.0f || top < -1.0f || left > 1.0f || bottom > 1.0f) return light;   // off the screen
    // [-1, 1] -> pixels (the last one is viewport - 1) -> tiles.
    const auto tileOf = [&](float ndc, int pixels, int tileCount, bool last) {
        float pixel = (std::min(std::max(ndc, -1.0f), 1.0f) * 0.5f + 0.5f) * static_cast<float>(pixels);
        if (last) pixel = std::min(pixel, static_cast<float>(pixels) - 1.0f);
        const int tile = static_cast<int>(std::floor(pixel)) / grid.tileSize;
        return std::min(std::max(tile, 0), tileCount - 1);
    };
    light.columnFirst = tileOf(left, grid.viewport.x, tiles.x, false);
    light.columnLast = tileOf(right, grid.viewport.x, tiles.x, true);
    light.rowFirst = tileOf(bottom, grid.viewport.y, tiles.y, false);
    light.rowLast = tileOf(top, grid.viewport.y, tiles.y, true);
    return light;
}

void TileLightBinner::markTiles(const Footprint& light, int index, int columns, int words) {
    const std::uint64_t bit = std::uint64_t{1} << (index % kBitsPerWord);
    const std::size_t word = static_cast<std::size_t>(index / kBitsPerWord);
    const float* tileNearest = m_tileNearest.data();
    const float* tileFarthest = m_tileFarthest.data();
    for (int row = light.rowFirst; row <= light.rowLast; ++row) {
        const std::size_t first = static_cast<std::size_t>(row) * static_cast<std::size_t>(columns);
        for (std::size_t t = first + static_cast<std::size_t>(light.columnFirst);
             t <= first + static_cast<std::size_t>(light.columnLast); ++t) {
            // False for a sky tile: its depths are NaN.
            const bool meets = light.nearest <= tileFarthest[t] && light.farthest >= tileNearest[t];
            m_bits[t * static_cast<std::size_t>(words) + word] |= bit & (std::uint64_t{0} - std::uint64_t{meets});
            m_counts[t] += meets;
        }
    }
}

void TileLightBinner::readLists(int tileCount, int words, TileLightLists& out) const {
    out.offsets.resize(static_cast<std::size_t>(tileCount) + 1);
    int total = 0;
    for (int t = 0; t < tileCount; ++t) {
        out.offsets[static_cast<std::size_t>(t)] = total;
        total += m_counts[static_cast<std::size_t>(t)];
    }
    out.offsets[static_cast<std::size_t>(tileCount)] = total;
    out.lights.resize(static_cast<std::size_t>(total));
    int* entry = out.lights.data();
    const std::uint64_t* bits = m_bits.data();
    for (int t = 0; t < tileCount; ++t) {
        for (int w = 0; w < words; ++w, ++bits) {
            // The set bits from the lowest: the tile's lights in increasing order.
            for (std::uint64_t left = *bits; left != 0; left &= left - 1)
                *entry++ = w * kBitsPerWord + __builtin_ctzll(left);
        }
    }
}

void TileLightBinner::assign(const std::vector<LightSphere>& spheres, const glm::mat4& projection, float near,
                             const TileGrid& grid, const std::vector<DepthRange>& depths, TileLightLists& out) {
    out.grid = grid;
    const int tileCount = grid.tileCount();
    const int columns = grid.tiles().x;
    const int words = std::max(1, static_cast<int>((spheres.size() + kBitsPerWord - 1) / kBitsPerWord));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    m_tileNearest.resize(static_cast<std::size_t>(tileCount));
    m_tileFarthest.resize(static_cast<std::size_t>(tileCount));
    for (std::size_t t = 0; t < static_cast<std::size_t>(tileCount); ++t) {
        const DepthRange& range = depths[t];
        m_tileNearest[t] = range.empty() ? nan : range.nearest;
        m_tileFarthest[t] = range.empty() ? nan : range.farthest;
    }
    m_bits.assign(static_cast<std::size_t>(tileCount) * static_cast<std::size_t>(words), 0);
    m_counts.assign(static_cast<std::size_t>(tileCount), 0);
    for (std::size_t i = 0; i < spheres.size(); ++i)
        markTiles(footprint(spheres[i], projection, near, grid), static_cast<int>(i), columns, words);
    readLists(tileCount, words, out);
}

} // namespace stoa
