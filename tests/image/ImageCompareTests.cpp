// compareImages() and differenceHeatMap(): what two correct renders may differ
// by passes (rounding, edges a pixel off); what a wrong render shows fails
// (a missing thin line, a changed area). The fast implementation is checked
// against a direct transcription of the definition on random images.

#include "catch.hpp"

#include <stoa/image/Flip.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using stoa::CompareOptions;
using stoa::CompareResult;
using stoa::compareImages;
using stoa::differenceHeatMap;
using stoa::Image;

namespace {

void fill(Image& image, int x0, int y0, int x1, int y1, glm::u8vec4 colour) {  // [x0, x1) x [y0, y1)
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) image.setPixel(x, y, colour);
}

// Black on the left, white from column `edgeX` on, with a grey square: sharp edges both ways.
Image edges(int size, int edgeX, int squareY) {
    Image image(size, size, 4);
    fill(image, edgeX, 0, size, size, {255, 255, 255, 255});
    fill(image, 20, squareY, 60, squareY + 40, {128, 64, 200, 255});
    return image;
}

// Smooth, with values that stay below 250 so that +3 never clips.
Image shaded(int width, int height) {
    Image image(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.setPixel(x, y, {std::uint8_t(x % 200), std::uint8_t(y % 200), std::uint8_t((x + y) % 240), 250});
    return image;
}

// The definition, written out directly: for each pixel the smallest
// max-channel difference over the clipped window, in both directions.
std::vector<int> slowDifference(const Image& actual, const Image& reference, int radius) {
    const int width = actual.width(), height = actual.height();
    auto oneWay = [&](const Image& from, const Image& to, int x, int y) {
        int best = 255;
        for (int dy = -radius; dy <= radius; ++dy)
            for (int dx = -radius; dx <= radius; ++dx) {
                const int qx = x + dx, qy = y + dy;
                if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
                const glm::u8vec4 p = from.pixel(x, y), q = to.pixel(qx, qy);
                int difference = 0;
                for (int c = 0; c < 4; ++c) difference = std::max(difference, std::abs(int(p[c]) - int(q[c])));
                best = std::min(best, difference);
            }
        return best;
    };
    std::vector<int> result;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            result.push_back(std::max(oneWay(actual, reference, x, y), oneWay(reference, actual, x, y)));
    return result;
}

} // namespace

TEST_CASE("compareImages: identical images pass with no error", "[image][compare]") {
    const Image image = edges(64, 30, 10);
    const CompareResult result = compareImages(image, image);
    CHECK(result.sameSize);
    CHECK(result.passed);
    CHECK(result.badFraction == 0.0);
    CHECK(result.maxError == 0);
    CHECK(result.meanError == 0.0);
    CHECK(result.summary == "0.00% of pixels beyond tolerance 12 (max 0, mean 0.00), FLIP mean 0.0000");
}

TEST_CASE("compareImages: edges shifted by one pixel pass", "[image][compare]") {
    const Image reference = edges(128, 64, 30);
    for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
        const Image actual = edges(128, 64 + dx, 30 + dy);
        const CompareResult result = compareImages(actual, reference);
        CHECK(result.passed);
        CHECK(result.maxError == 0);
        // Without the shift search the same images are far apart.
        CompareOptions exact;
        exact.searchRadius = 0;
        const CompareResult strict = compareImages(actual, reference, exact);
        CHECK_FALSE(strict.passed);
        CHECK(strict.maxError >= 200);
    }
    // Two pixels is beyond the default radius.
    CHECK_FALSE(compareImages(edges(128, 66, 30), reference).passed);
}

TEST_CASE("compareImages: a few levels everywhere pass within the tolerance", "[image][compare]") {
    const Image reference = shaded(97, 61);
    Image actual = reference;
    for (std::size_t i = 0; i < actual.sizeInBytes(); ++i) actual.data()[i] += 3;
    const CompareResult result = compareImages(actual, reference);
    CHECK(result.passed);
    CHECK(result.badFraction == 0.0);
    CHECK(result.maxError <= 3);
    CHECK(result.meanError <= 3.0);
    CHECK(result.meanError > 0.0);

    CompareOptions tight;
    tight.tolerance = 0;
    CHECK_FALSE(compareImages(actual, reference, tight).passed);
}

TEST_CASE("compareImages: a missing thin line fails", "[image][compare]") {
    Image reference(128, 128, 4);
    fill(reference, 0, 64, 128, 65, {255, 255, 255, 255});  // 1 pixel high, 0.78% of the image
    const Image actual(128, 128, 4);

    const CompareResult result = compareImages(actual, reference);
    CHECK_FALSE(result.passed);
    CHECK(result.maxError == 255);
    CHECK(result.badFraction == Approx(128.0 / (128 * 128)));
    // And the other way round: a line that should not be there.
    CHECK_FALSE(compareImages(reference, actual).passed);

    // The same line one pixel lower passes.
    Image shifted(128, 128, 4);
    fill(shifted, 0, 65, 128, 66, {255, 255, 255, 255});
    CHECK(compareImages(shifted, reference).passed);
}

TEST_CASE("compareImages: a changed area fails", "[image][compare]") {
    const Image reference = edges(128, 64, 30);
    Image actual = reference;
    fill(actual, 70, 70, 110, 110, {0, 128, 0, 255});
    const CompareResult result = compareImages(actual, reference);
    CHECK_FALSE(result.passed);
    CHECK(result.badFraction > 0.05);
    CHECK(result.maxError == 255);
    CHECK(result.summary.find("% of pixels beyond tolerance 12 (max 255, mean ") == 4);
}

TEST_CASE("compareImages: alpha counts", "[image][compare]") {
    const Image reference = shaded(40, 40);
    Image actual = reference;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) actual.data()[(y * 40 + x) * 4 + 3] = 0;
    CHECK_FALSE(compareImages(actual, reference).passed);
}

TEST_CASE("compareImages: images of other channel counts are compared as RGBA", "[image][compare]") {
    const Image rgba = shaded(30, 20);
    const CompareResult rgb = compareImages(rgba.converted(3), rgba.converted(3).converted(4));
    CHECK(rgb.passed);
    CHECK(rgb.maxError == 0);
    // An opaque RGB image against an RGBA reference whose alpha is 250: 5 levels off.
    const CompareResult mixed = compareImages(rgba.converted(3), rgba);
    CHECK(mixed.passed);
    CHECK(mixed.maxError == 5);
    CHECK(compareImages(rgba.converted(1), rgba.converted(1).converted(4)).maxError == 0);
}

TEST_CASE("compareImages: images of different sizes fail", "[image][compare]") {
    const CompareResult result = compareImages(Image(256, 256, 4), Image(512, 512, 4));
    CHECK_FALSE(result.sameSize);
    CHECK_FALSE(result.passed);
    CHECK(result.badFraction == 1.0);
    CHECK(result.summary == "size 256x256 differs from the reference's 512x512");
    CHECK_FALSE(compareImages(Image(10, 20, 4), Image(20, 10, 4)).sameSize);
}

TEST_CASE("compareImages: the summary states the numbers", "[image][compare]") {
    const Image reference(50, 50, 4);
    Image actual = reference;
    actual.setPixel(25, 25, {255, 255, 255, 255});  // one pixel of 2500
    const CompareResult one = compareImages(actual, reference);
    char flip[32];
    std::snprintf(flip, sizeof flip, "%.4f", stoa::computeFlip(actual, reference).mean);
    CHECK(one.summary == std::string("0.04% of pixels beyond tolerance 12 (max 255, mean 0.10), FLIP mean ") + flip);
    CHECK(one.badFraction == Approx(1.0 / 2500));
    CHECK(one.passed == (1.0 / 2500 <= CompareOptions().maxBadFraction && one.flipMean <= CompareOptions().maxFlipMean));

    // A single bad pixel in a large image does not read as 0.00%.
    const Image large(512, 512, 4);
    Image dotted = large;
    dotted.setPixel(100, 100, {255, 0, 0, 255});
    CHECK(compareImages(dotted, large).summary.find("0.00038% of pixels") == 0);
}

TEST_CASE("compareImages: the fast search agrees with the definition", "[image][compare]") {
    std::mt19937 random(12345);
    auto byte = [&] { return std::uint8_t(random() & 255); };
    const std::pair<int, int> sizes[] = {{1, 1}, {1, 7}, {7, 1}, {33, 5}, {64, 3}, {65, 17}, {31, 40}};
    for (const auto& [width, height] : sizes) {
        for (int radius = 0; radius <= 2; ++radius) {
            for (bool sparse : {true, false}) {
                Image reference(width, height, 4), actual(width, height, 4);
                for (std::size_t i = 0; i < reference.sizeInBytes(); ++i) reference.data()[i] = byte();
                for (std::size_t i = 0; i < actual.sizeInBytes(); ++i) {
                    const int noise = int(random() % 41) - 20;
                    const bool change = !sparse || random() % 8 == 0;
                    actual.data()[i] = change ? std::uint8_t(std::clamp(reference.data()[i] + noise, 0, 255))
                                              : reference.data()[i];
                }
                const std::vector<int> expected = slowDifference(actual, reference, radius);
                const int expectedMax = *std::max_element(expected.begin(), expected.end());
                double expectedSum = 0;
                for (int d : expected) expectedSum += d;

                for (int tolerance : {0, 5, 12}) {
                    CompareOptions options;
                    options.searchRadius = radius;
                    options.tolerance = tolerance;
                    const CompareResult result = compareImages(actual, reference, options);
                    INFO(width << "x" << height << " radius " << radius << " tolerance " << tolerance
                                << (sparse ? " sparse" : " dense"));
                    const auto bad = std::count_if(expected.begin(), expected.end(), [&](int d) { return d > tolerance; });
                    CHECK(result.maxError == expectedMax);
                    CHECK(result.meanError == Approx(expectedSum / expected.size()));
                    CHECK(result.badFraction == Approx(double(bad) / expected.size()));

                    const Image heat = differenceHeatMap(actual, reference, options);
                    if (expectedMax <= tolerance) {
                        // The fast path: the shift-tolerant picture, no FLIP.
                        CHECK(result.flipMean == 0.0);
                        CHECK(result.flipErrorMap.empty());
                        bool heatAgrees = true;
                        for (int i = 0; i < width * height; ++i) {
                            const glm::u8vec4 colour = heat.pixel(i % width, i / width);
                            heatAgrees = heatAgrees && (expected[i] == 0) == (colour == glm::u8vec4(0, 0, 0, 255)) &&
                                         colour.r <= 128;
                        }
                        CHECK(heatAgrees);
                    } else {
                        // FLIP ran: its mean, and its heat map, also from the computed result.
                        const stoa::FlipResult flip = stoa::computeFlip(actual, reference);
                        CHECK(result.flipMean == flip.mean);
                        CHECK(result.flipErrorMap == flip.errorMap);
                        const Image flipHeat = flip.heatMap();
                        CHECK(std::equal(heat.data(), heat.data() + heat.sizeInBytes(), flipHeat.data()));
                        const Image reused = differenceHeatMap(actual, reference, result, options);
                        CHECK(std::equal(reused.data(), reused.data() + reused.sizeInBytes(), flipHeat.data()));
                    }
                }
            }
        }
    }
}

TEST_CASE("differenceHeatMap: FLIP's heat map where the images differ beyond the tolerance", "[image][compare]") {
    const Image reference = edges(64, 32, 10);
    Image actual = reference;
    fill(actual, 40, 40, 50, 50, {0, 0, 255, 255});  // a blue square on white

    const Image heat = differenceHeatMap(actual, reference);
    REQUIRE(heat.width() == 64);
    REQUIRE(heat.height() == 64);
    const Image flip = stoa::computeFlip(actual, reference).heatMap();
    CHECK(std::equal(heat.data(), heat.data() + heat.sizeInBytes(), flip.data()));
    const glm::u8vec4 inside = heat.pixel(45, 45), far = heat.pixel(5, 60);
    CHECK(int(inside.r) + inside.g + inside.b > 3 * (int(far.r) + far.g + far.b));
    CHECK(int(far.r) + far.g + far.b < 20);  // FLIP's zero: near black
}

TEST_CASE("differenceHeatMap: within the tolerance, black where equal and dark red where not", "[image][compare]") {
    const Image reference = edges(64, 32, 10);
    Image rounded = reference;
    rounded.setPixel(5, 5, {6, 0, 0, 255});
    const Image heat = differenceHeatMap(rounded, reference);
    const glm::u8vec4 withinTolerance = heat.pixel(5, 5);
    CHECK(int(withinTolerance.r) > 0);
    CHECK(int(withinTolerance.r) <= 128);
    CHECK(int(withinTolerance.g) == 0);
    CHECK(heat.pixel(0, 0) == glm::u8vec4(0, 0, 0, 255));

    const Image same = differenceHeatMap(reference, reference);
    CHECK(same.pixel(32, 32) == glm::u8vec4(0, 0, 0, 255));
}

TEST_CASE("compareImages: FLIP runs only beyond the floor and its mean gates the result", "[image][compare]") {
    const Image reference = shaded(64, 64);
    SECTION("identical: FLIP skipped, mean 0") {
        const CompareResult result = compareImages(reference, reference);
        CHECK(result.flipMean == 0.0);
        CHECK(result.passed);
        CHECK(result.summary.find("FLIP mean 0.0000") != std::string::npos);
    }
    SECTION("rounding within the tolerance: FLIP skipped") {
        Image rounded = reference;
        for (std::size_t i = 0; i < rounded.sizeInBytes(); i += 4) rounded.data()[i] += 2;
        const CompareResult result = compareImages(rounded, reference);
        CHECK(result.maxError == 2);
        CHECK(result.flipMean == 0.0);
        CHECK(result.flipErrorMap.empty());
        CHECK(result.passed);
    }
    SECTION("a shade changed everywhere: a gate loosened to let it through, FLIP does not") {
        Image tinted = reference;
        for (std::size_t i = 0; i < tinted.sizeInBytes(); i += 4) tinted.data()[i] += 20;
        CompareOptions options;
        options.maxBadFraction = 1.0;
        CompareResult result = compareImages(tinted, reference, options);
        CHECK(result.badFraction == 1.0);
        CHECK(result.flipMean > options.maxFlipMean);
        CHECK_FALSE(result.passed);
        options.maxFlipMean = 1.0;
        result = compareImages(tinted, reference, options);
        CHECK(result.passed);
    }
    SECTION("different sizes: no FLIP") {
        const CompareResult result = compareImages(Image(8, 8, 4), Image(9, 8, 4));
        CHECK(result.flipMean == -1.0);
        CHECK_FALSE(result.passed);
    }
}
