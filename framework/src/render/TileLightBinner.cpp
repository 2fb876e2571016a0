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

} // namespace

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
