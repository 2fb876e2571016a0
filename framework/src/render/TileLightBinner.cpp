#include "TileLightBinner.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace stoa {

namespace {

constexpr int kBitsPerWord = 64;

// Window depth d in [0, 1) -> distance in front of the camera. With the
// normalised depth n = 2 d - 1, z_view = -P[3][2] / (n + P[2][2]). Each
// operation is rounded monotonically and the result grows with d, so the
// distance of a tile's smallest (largest) depth is its smallest (largest)
// distance, bit for bit.
float distanceOf(float windowDepth, float p22, float p32) { return p32 / (2.0f * windowDepth - 1.0f + p22); }

// The smallest and the largest of `count` window depths, sky (1) left out,
// folded into `low` and `high`. With SSE2 four at a time: depths are never NaN
// and never -0, so the order of the comparisons cannot change the result.
void rowExtremes(const float* depth, int count, float& low, float& high) {
    int x = 0;
#if defined(__SSE2__)
    if (count >= 4) {
        const __m128 one = _mm_set1_ps(1.0f), skyLow = _mm_set1_ps(2.0f), skyHigh = _mm_set1_ps(-1.0f);
        __m128 lows = _mm_set1_ps(low), highs = _mm_set1_ps(high);
        for (; x + 4 <= count; x += 4) {
            const __m128 d = _mm_loadu_ps(depth + x);
            const __m128 sky = _mm_cmpge_ps(d, one);
            lows = _mm_min_ps(lows, _mm_or_ps(_mm_and_ps(sky, skyLow), _mm_andnot_ps(sky, d)));
            highs = _mm_max_ps(highs, _mm_or_ps(_mm_and_ps(sky, skyHigh), _mm_andnot_ps(sky, d)));
        }
        lows = _mm_min_ps(lows, _mm_shuffle_ps(lows, lows, _MM_SHUFFLE(1, 0, 3, 2)));
        lows = _mm_min_ps(lows, _mm_shuffle_ps(lows, lows, _MM_SHUFFLE(2, 3, 0, 1)));
        highs = _mm_max_ps(highs, _mm_shuffle_ps(highs, highs, _MM_SHUFFLE(1, 0, 3, 2)));
        highs = _mm_max_ps(highs, _mm_shuffle_ps(highs, highs, _MM_SHUFFLE(2, 3, 0, 1)));
        low = _mm_cvtss_f32(lows);
        high = _mm_cvtss_f32(highs);
    }
#endif
    for (; x < count; ++x) {
        const bool sky = depth[x] >= 1.0f;
        low = std::min(low, sky ? 2.0f : depth[x]);
        high = std::max(high, sky ? -1.0f : depth[x]);
    }
}

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
            rowExtremes(row + begin, end - begin, low, high);
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

long TileLightBinner::markTiles(const Footprint& light, int index, int columns, int tileCount) {
    const std::uint64_t bit = std::uint64_t{1} << (index % kBitsPerWord);
    // The bits of this light's word: one per tile, in the tiles' order, so a row of tiles is a run of words.
    std::uint64_t* bits = m_bits.data() + static_cast<std::size_t>(index / kBitsPerWord) * static_cast<std::size_t>(tileCount);
    const float* tileNearest = m_tileNearest.data();
    const float* tileFarthest = m_tileFarthest.data();
    long marked = 0;
    for (int row = light.rowFirst; row <= light.rowLast; ++row) {
        int t = row * columns + light.columnFirst;
        const int last = row * columns + light.columnLast;
#if defined(__SSE2__)
        // Four tiles at a time: the two comparisons give four 32-bit masks,
        // each widened to the 64 bits of its tile's word.
        const __m128 lightNearest = _mm_set1_ps(light.nearest), lightFarthest = _mm_set1_ps(light.farthest);
        const __m128i bits2 = _mm_set1_epi64x(static_cast<long long>(bit));
        __m128i counts = _mm_setzero_si128();
        for (; t + 3 <= last; t += 4) {
            const __m128 meets = _mm_and_ps(_mm_cmple_ps(lightNearest, _mm_loadu_ps(tileFarthest + t)),
                                            _mm_cmpge_ps(lightFarthest, _mm_loadu_ps(tileNearest + t)));
            const __m128i mask = _mm_castps_si128(meets);
            __m128i* words = reinterpret_cast<__m128i*>(bits + t);
            _mm_storeu_si128(words, _mm_or_si128(_mm_loadu_si128(words), _mm_and_si128(bits2, _mm_unpacklo_epi32(mask, mask))));
            _mm_storeu_si128(words + 1,
                             _mm_or_si128(_mm_loadu_si128(words + 1), _mm_and_si128(bits2, _mm_unpackhi_epi32(mask, mask))));
            counts = _mm_sub_epi32(counts, mask);
        }
        alignas(16) int lanes[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(lanes), counts);
        marked += lanes[0] + lanes[1] + lanes[2] + lanes[3];
#endif
        for (; t <= last; ++t) {
            // False for a sky tile: its depths are NaN.
            const bool meets = light.nearest <= tileFarthest[t] && light.farthest >= tileNearest[t];
            bits[t] |= bit & (std::uint64_t{0} - static_cast<std::uint64_t>(meets));
            marked += meets;
        }
    }
    return marked;
}

void TileLightBinner::readLists(int tileCount, int words, long entries, TileLightLists& out) const {
    const std::size_t stride = static_cast<std::size_t>(tileCount);
    out.offsets.resize(stride + 1);
    out.lights.resize(static_cast<std::size_t>(entries));
    int* const first = out.lights.data();
    int* entry = first;
    for (std::size_t t = 0; t < stride; ++t) {
        out.offsets[t] = static_cast<int>(entry - first);
        for (int w = 0; w < words; ++w) {
            // The set bits from the lowest: the tile's lights in increasing order.
            for (std::uint64_t left = m_bits[static_cast<std::size_t>(w) * stride + t]; left != 0; left &= left - 1)
                *entry++ = w * kBitsPerWord + __builtin_ctzll(left);
        }
    }
    out.offsets[stride] = static_cast<int>(entry - first);
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
    long entries = 0;
    for (std::size_t i = 0; i < spheres.size(); ++i)
        entries += markTiles(footprint(spheres[i], projection, near, grid), static_cast<int>(i), columns, tileCount);
    readLists(tileCount, words, entries, out);
}

} // namespace stoa
