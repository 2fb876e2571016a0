#include "HeatMapLegend.hpp"

#include <stoa/image/Flip.hpp>

#include <cstdio>

namespace stoa::grader {

namespace {

constexpr int kWidth = 512;
constexpr int kBarHeight = 32;
constexpr int kTickHeight = 8;

} // namespace

Image heatMapLegend() {
    Image legend(kWidth, kBarHeight + kTickHeight, 4);
    for (int x = 0; x < kWidth; ++x) {
        std::uint8_t rgb[3];
        flipHeatColor(static_cast<float>(x) / (kWidth - 1), rgb);
        for (int y = 0; y < kBarHeight; ++y) legend.setPixel(x, y, {rgb[0], rgb[1], rgb[2], 255});
        for (int y = kBarHeight; y < kBarHeight + kTickHeight; ++y) legend.setPixel(x, y, {255, 255, 255, 0});
    }
    for (int quarter = 0; quarter <= 4; ++quarter) {
        int centre = quarter * (kWidth - 1) / 4;
        for (int x = centre - 1; x <= centre + 1; ++x)
            if (x >= 0 && x < kWidth)
                for (int y = kBarHeight; y < kBarHeight + kTickHeight; ++y) legend.setPixel(x, y, {128, 128, 128, 255});
    }
    return legend;
}

std::string heatMapLegendGradient() {
    std::string css = "linear-gradient(to right";
    for (int step = 0; step <= 10; ++step) {
        std::uint8_t rgb[3];
        flipHeatColor(step / 10.0f, rgb);
        char stop[48];
        std::snprintf(stop, sizeof stop, ", #%02x%02x%02x %d%%", rgb[0], rgb[1], rgb[2], step * 10);
        css += stop;
    }
    return css + ")";
}

void writeHeatMapLegend(const std::filesystem::path& path) { heatMapLegend().savePng(path); }

} // namespace stoa::grader
