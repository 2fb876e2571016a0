#include "TileDepthRanges.hpp"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace stoa {

namespace {

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

const std::vector<DepthRange>& TileDepthRanges::compute(const float* windowDepth, glm::ivec2 size,
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

} // namespace stoa
