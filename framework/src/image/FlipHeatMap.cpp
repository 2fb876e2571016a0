// FLIP's heat map: the error map through a magma-like colour map.

#include <stoa/image/Flip.hpp>

#include <stoa/core/Assert.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

void flipHeatColor(float error, std::uint8_t rgb[3]) {
    // Samples of a magma-like ramp at 0, 1/8, ..., 1 (dark purple, red, orange, pale yellow).
    static constexpr float kRamp[9][3] = {{0.001f, 0.000f, 0.014f}, {0.079f, 0.054f, 0.212f},
                                          {0.232f, 0.060f, 0.438f}, {0.390f, 0.100f, 0.502f},
                                          {0.550f, 0.161f, 0.506f}, {0.716f, 0.215f, 0.475f},
                                          {0.869f, 0.288f, 0.409f}, {0.968f, 0.440f, 0.360f},
                                          {0.987f, 0.991f, 0.750f}};
    const float t = std::clamp(std::isnan(error) ? 1.0f : error, 0.0f, 1.0f) * 8.0f;
    const int low = std::min(static_cast<int>(t), 7);
    const float f = t - static_cast<float>(low);
    for (int c = 0; c < 3; ++c) {
        const float value = kRamp[low][c] + f * (kRamp[low + 1][c] - kRamp[low][c]);
        rgb[c] = static_cast<std::uint8_t>(std::lround(255.0f * value));
    }
}

Image FlipResult::heatMap() const {
    STOA_ASSERT(errorMap.size() == static_cast<std::size_t>(width) * height,
                "FlipResult::heatMap(): errorMap does not hold width x height values.");
    Image heat(width, height, 4);
    std::uint8_t* out = heat.data();
    for (const float error : errorMap) {
        flipHeatColor(error, out);
        out[3] = 255;
        out += 4;
    }
    return heat;
}

} // namespace stoa
