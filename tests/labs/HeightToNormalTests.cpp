// Lab 04's normalMapFromHeight() on height maps whose slopes are known: flat,
// ramps along x and along the rows, a ridge across the wrapped border.

#include "catch.hpp"
#include "lab04.hpp"

#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace {

stoa::Image heightFrom(int width, int height, int (*value)(int x, int y)) {
    stoa::Image image(width, height, 1);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.setPixel(x, y, glm::u8vec4(static_cast<std::uint8_t>(value(x, y))));
    return image;
}

// The packing the docs give: round((n * 0.5 + 0.5) * 255), per component.
glm::ivec3 packed(glm::vec3 n) { return glm::ivec3(glm::round((glm::normalize(n) * 0.5f + 0.5f) * 255.0f)); }

glm::ivec3 rgb(const stoa::Image& image, int x, int y) { return glm::ivec3(glm::u8vec3(image.pixel(x, y))); }

bool near(glm::ivec3 a, glm::ivec3 b, int tolerance = 1) {
    const glm::ivec3 d = glm::abs(a - b);
    return d.x <= tolerance && d.y <= tolerance && d.z <= tolerance;
}

} // namespace

TEST_CASE("normalMapFromHeight: a flat height map is (0, 0, 1) everywhere: RGB (128, 128, 255)") {
    const stoa::Image normals = normalMapFromHeight(heightFrom(5, 4, [](int, int) { return 77; }), 4.0f);
    REQUIRE(normals.width() == 5);
    REQUIRE(normals.height() == 4);
    REQUIRE(normals.channels() == 3);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) CHECK(rgb(normals, x, y) == glm::ivec3(128, 128, 255));
}

TEST_CASE("normalMapFromHeight: rising to the right tilts the normal towards -u (red below 128)") {
    // h = 10 x / 255 per texel: dh/du = 10 / 255 away from the wrapped border.
    const float strength = 3.0f;
    const stoa::Image normals = normalMapFromHeight(heightFrom(8, 3, [](int x, int) { return 10 * x; }), strength);
    const glm::vec3 expected(-strength * 10.0f / 255.0f, 0.0f, 1.0f);
    for (int y = 0; y < 3; ++y)
        for (int x = 1; x < 7; ++x) CHECK(near(rgb(normals, x, y), packed(expected)));
    CHECK(rgb(normals, 3, 1).r < 128);
}

TEST_CASE("normalMapFromHeight: rows go down, v goes up: heights rising down the image tilt the normal to +v") {
    // h grows with the row index, so it falls as v grows: dh/dv = -12 / 255.
    const float strength = 5.0f;
    const stoa::Image normals = normalMapFromHeight(heightFrom(3, 8, [](int, int y) { return 12 * y; }), strength);
    const glm::vec3 expected(0.0f, strength * 12.0f / 255.0f, 1.0f);
    for (int y = 1; y < 7; ++y)
        for (int x = 0; x < 3; ++x) CHECK(near(rgb(normals, x, y), packed(expected)));
    CHECK(rgb(normals, 1, 4).g > 128);
}

TEST_CASE("normalMapFromHeight: the borders wrap around (the maps tile)") {
    // One raised column at the right edge: texel 0 sees it as its left neighbour.
    const stoa::Image normals = normalMapFromHeight(heightFrom(6, 2, [](int x, int) { return x == 5 ? 255 : 0; }), 2.0f);
    // dh/du at x = 0 is (h(1) - h(-1 -> 5)) / 2 = -0.5: the normal leans to +u.
    CHECK(near(rgb(normals, 0, 0), packed({2.0f * 0.5f, 0.0f, 1.0f})));
    // and at x = 4 it is (h(5) - h(3)) / 2 = +0.5: leaning to -u.
    CHECK(near(rgb(normals, 4, 1), packed({-2.0f * 0.5f, 0.0f, 1.0f})));
    // The ridge itself is a local maximum: flat.
    CHECK(rgb(normals, 5, 0) == glm::ivec3(128, 128, 255));
}

TEST_CASE("normalMapFromHeight: a larger strength tilts further, and the packed normals stay unit length") {
    const auto bumpy = [](int x, int y) { return (x * 37 + y * 91 + x * y * 13) % 256; };
    const stoa::Image gentle = normalMapFromHeight(heightFrom(9, 7, bumpy), 1.0f);
    const stoa::Image steep = normalMapFromHeight(heightFrom(9, 7, bumpy), 8.0f);
    for (int y = 0; y < 7; ++y) {
        for (int x = 0; x < 9; ++x) {
            const glm::vec3 a = glm::vec3(rgb(gentle, x, y)) / 255.0f * 2.0f - 1.0f;
            const glm::vec3 b = glm::vec3(rgb(steep, x, y)) / 255.0f * 2.0f - 1.0f;
            CHECK(std::abs(glm::length(a) - 1.0f) < 0.02f);
            CHECK(std::abs(glm::length(b) - 1.0f) < 0.02f);
            CHECK(b.z <= a.z + 0.01f);  // steeper: less of the normal along the surface normal
        }
    }
}
