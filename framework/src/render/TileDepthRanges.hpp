#pragma once
// Each tile's range of depths, for the tiled pass of the deferred renderer
// (docs/labs/08_deferred.md, "Depth bounds"): the nearest and the farthest
// distance in front of the camera among a tile's pixels, sky left out. Private
// to libstoa; what every tile list is built from, the student's and the
// framework's alike. How fast: tests/benchmarks/light_assignment_benchmark.cpp.

#include <stoa/render/DeferredShading.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <vector>

namespace stoa {

class TileDepthRanges {
public:
    /// Each tile's depth range (distances in front of the camera, metres)
    /// from `windowDepth`, the depth buffer's values in [0, 1] of a
    /// `size.x` x `size.y` picture, rows from the bottom; 1 is sky. The
    /// values equal those of a per-pixel conversion then min/max: the
    /// conversion is monotonic, so it is applied to each tile's extremes only.
    /// The result stays valid until the next call.
    const std::vector<DepthRange>& compute(const float* windowDepth, glm::ivec2 size, const glm::mat4& projection,
                                           const TileGrid& grid);

private:
    std::vector<DepthRange> m_ranges;
    std::vector<float> m_lowest, m_highest;   // per tile, scratch of compute()
};

} // namespace stoa
