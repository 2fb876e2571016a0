// Lab 04's property checks; see checks.hpp. They call your normalMapFromHeight()
// on height maps of their own and test a property the docs state, not values.

#include "checks.hpp"
#include "lab04.hpp"

#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <cstdint>
#include <cstdlib>
#include <string>

namespace lab04 {

namespace {

// A small height map of random heights (a fixed seed: the same map every run).
stoa::Image randomHeights(int width, int height) {
    stoa::Image image(width, height, 1);
    std::uint32_t state = 20261123u;
    for (int i = 0; i < width * height; ++i) {
        state = state * 1664525u + 1013904223u;   // a linear congruential generator
        image.data()[i] = static_cast<std::uint8_t>(state >> 24);
    }
    return image;
}

// `image` moved right by dx and down by dy as a tile: what leaves one border comes in at the other.
stoa::Image shiftedAround(const stoa::Image& image, int dx, int dy) {
    stoa::Image shifted(image.width(), image.height(), image.channels());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            shifted.setPixel((x + dx) % image.width(), (y + dy) % image.height(), image.pixel(x, y));
    return shifted;
}

} // namespace

stoa::CheckResult checkNormalMapWraps() {
    const int width = 24, height = 16, dx = 7, dy = 5;
    const float strength = 4.0f;
    const stoa::Image heights = randomHeights(width, height);
    const stoa::Image expected = shiftedAround(stoa::normalMapFromHeight(heights, strength), dx, dy);
    const stoa::Image normals = stoa::normalMapFromHeight(shiftedAround(heights, dx, dy), strength);
    if (normals.width() != width || normals.height() != height || normals.channels() < 3)
        return stoa::CheckResult::fail("normalMapFromHeight() returned a " + std::to_string(normals.width()) + "x" +
                                       std::to_string(normals.height()) + " image with " +
                                       std::to_string(normals.channels()) + " channels for a " +
                                       std::to_string(width) + "x" + std::to_string(height) +
                                       " height map (expected the same size, RGB)");

    // Texels whose normal is not the shifted one; they are told apart by where they lie.
    int differing = 0, onBorder = 0, firstX = -1, firstY = -1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::u8vec4 a = normals.pixel(x, y), b = expected.pixel(x, y);
            bool same = true;
            for (int c = 0; c < 3; ++c) same = same && std::abs(int(a[c]) - int(b[c])) <= 1;
            if (same) continue;
            if (differing++ == 0) firstX = x, firstY = y;
            // On a border of the shifted map, or where a border of the original one landed.
            const int sourceX = (x - dx + width) % width, sourceY = (y - dy + height) % height;
            if (x == 0 || y == 0 || x == width - 1 || y == height - 1 || sourceX == 0 || sourceY == 0 ||
                sourceX == width - 1 || sourceY == height - 1)
                ++onBorder;
        }
    const std::string shift = "shifting a " + std::to_string(width) + "x" + std::to_string(height) +
                              " height map around by (" + std::to_string(dx) + ", " + std::to_string(dy) + ") texels";
    if (differing == 0) return stoa::CheckResult::pass(shift + " shifts its normal map by the same texels");
    std::string where = " (first at texel (" + std::to_string(firstX) + ", " + std::to_string(firstY) + ") of the shifted map)";
    if (onBorder == differing)
        return stoa::CheckResult::fail(shift + " changed " + std::to_string(differing) +
                                       " normals next to the borders of the map" + where +
                                       ": the maps tile, so the neighbour left of column 0 is the last column and the "
                                       "row above row 0 is the last row (docs: From heights to normals)");
    return stoa::CheckResult::fail(shift + " changed " + std::to_string(differing) + " normals, " +
                                   std::to_string(differing - onBorder) + " of them away from the borders" + where +
                                   ": a texel's normal must depend only on the heights around it "
                                   "(docs: From heights to normals)");
}

} // namespace lab04
