// computeFlip(): the properties the FLIP paper states or implies, checked on
// small synthetic images: no error for equal images, the largest error for the
// largest colour difference, errors that grow with the difference, features
// (a missing thin line) that count, and filtering that depends on the viewing
// distance (pixels per degree).

#include "catch.hpp"

#include <stoa/image/Flip.hpp>

#include <algorithm>
#include <random>

using stoa::computeFlip;
using stoa::FlipOptions;
using stoa::FlipResult;
using stoa::Image;

namespace {

Image solid(int width, int height, glm::u8vec4 colour) {
    Image image(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.setPixel(x, y, colour);
    return image;
}

float at(const FlipResult& result, int x, int y) { return result.errorMap.at(std::size_t(y) * result.width + x); }

} // namespace

TEST_CASE("computeFlip: equal images have no error", "[image][flip]") {
    Image image(40, 30, 4);
    std::mt19937 random(7);
    for (std::size_t i = 0; i < image.sizeInBytes(); ++i) image.data()[i] = std::uint8_t(random() & 255);
    const FlipResult result = computeFlip(image, image);
    CHECK(result.width == 40);
    CHECK(result.height == 30);
    REQUIRE(result.errorMap.size() == 40u * 30u);
    CHECK(result.mean == 0.0);
    CHECK(*std::max_element(result.errorMap.begin(), result.errorMap.end()) == 0.0f);
}

TEST_CASE("computeFlip: black against white is close to the largest error", "[image][flip]") {
    const FlipResult result = computeFlip(solid(64, 64, {0, 0, 0, 255}), solid(64, 64, {255, 255, 255, 255}));
    CHECK(at(result, 32, 32) > 0.9f);
    CHECK(result.mean > 0.9);
    // Green against blue is the difference the paper scales to 1.
    const FlipResult largest = computeFlip(solid(32, 32, {0, 255, 0, 255}), solid(32, 32, {0, 0, 255, 255}));
    CHECK(at(largest, 16, 16) == Approx(1.0f).margin(1e-4));
}

TEST_CASE("computeFlip: a small colour shift is a small error, a larger shift a larger one", "[image][flip]") {
    const Image reference = solid(48, 48, {128, 100, 90, 255});
    const double slight = computeFlip(solid(48, 48, {131, 100, 90, 255}), reference).mean;
    const double more = computeFlip(solid(48, 48, {140, 100, 90, 255}), reference).mean;
    const double much = computeFlip(solid(48, 48, {200, 100, 90, 255}), reference).mean;
    // 3 levels of red is about one unit of HyAB: 1^0.7 / (0.4 cmax) x 0.95, some 0.06.
    CHECK(slight > 0.0);
    CHECK(slight < 0.1);
    CHECK(slight < more);
    CHECK(more < much);
}

TEST_CASE("computeFlip: a missing one-pixel line shows at the line", "[image][flip]") {
    Image reference = solid(64, 64, {60, 60, 60, 255});
    for (int y = 0; y < 64; ++y) reference.setPixel(32, y, {230, 230, 230, 255});
    const Image test = solid(64, 64, {60, 60, 60, 255});
    const FlipResult result = computeFlip(test, reference);
    CHECK(at(result, 32, 32) > 0.2f);
    CHECK(at(result, 2, 32) < 0.01f);                         // far from the line: nothing
    CHECK(at(result, 32, 32) > 20.0f * at(result, 10, 32));   // the error sits at the line

    // Seen from further away (more pixels per degree) the contrast-sensitivity
    // filters blur the thin line more: its colour error at the line is smaller.
    FlipOptions far;
    far.pixelsPerDegree = 200.0;
    CHECK(at(computeFlip(test, reference, far), 32, 32) < at(result, 32, 32));
}

TEST_CASE("computeFlip: errors stay in [0, 1]; RGB and RGBA read alike", "[image][flip]") {
    std::mt19937 random(99);
    Image a(37, 23, 4), b(37, 23, 4);
    for (std::size_t i = 0; i < a.sizeInBytes(); ++i) {
        a.data()[i] = std::uint8_t(random() & 255);
        b.data()[i] = std::uint8_t(random() & 255);
    }
    const FlipResult result = computeFlip(a, b);
    CHECK(*std::min_element(result.errorMap.begin(), result.errorMap.end()) >= 0.0f);
    CHECK(*std::max_element(result.errorMap.begin(), result.errorMap.end()) <= 1.0f);
    CHECK(result.mean > 0.1);
    const FlipResult rgb = computeFlip(a.converted(3), b.converted(3));
    CHECK(rgb.mean == result.mean);
    // Alpha is not FLIP's business.
    Image transparent = a;
    for (std::size_t i = 3; i < transparent.sizeInBytes(); i += 4) transparent.data()[i] = 0;
    CHECK(computeFlip(transparent, a).mean == 0.0);

    const FlipResult empty = computeFlip(Image(), Image());
    CHECK(empty.mean == 0.0);
    CHECK(empty.errorMap.empty());
}

TEST_CASE("FlipResult::heatMap: dark for no error, bright yellow for the largest", "[image][flip]") {
    FlipResult result;
    result.width = 3;
    result.height = 1;
    result.errorMap = {0.0f, 0.5f, 1.0f};
    const Image heat = result.heatMap();
    REQUIRE(heat.width() == 3);
    REQUIRE(heat.height() == 1);
    const glm::u8vec4 none = heat.pixel(0, 0), half = heat.pixel(1, 0), full = heat.pixel(2, 0);
    CHECK(int(none.r) + none.g + none.b < 10);
    CHECK(int(half.r) > int(half.g));                 // purple-red in the middle
    CHECK(int(full.r) > 240);
    CHECK(int(full.g) > 240);                         // pale yellow at the top
    CHECK(int(full.r) + full.g + full.b > int(half.r) + half.g + half.b);
    CHECK(none.a == 255);
    CHECK(full.a == 255);
}
