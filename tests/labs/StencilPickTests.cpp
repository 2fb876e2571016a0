// Lab 11's stencil pick (labs/11_editor/student/lab11.hpp) against an
// independent reference written here:
//   - objectAtPixel on small read-backs made by hand: the window's y flipped
//     (the read-back's first row is the bottom one), background 0 gives -1 and
//     value v the index v - 1, the nearest object pixel within the radius by
//     Euclidean distance, ties to the pixel first in the read-back's order,
//     radius 0, outside the read-back; then against a scan of every pixel in
//     the read-back's order on 3,000 random read-backs, mice and radii.
// The planted mistakes of solutions/11_editor/mistakes/ for it each fail cases
// here (checked by applying each one's find/replace to a copy of the solutions):
//   background_is_an_object    objectAtPixel "flips y", "value v", "radius 0", "random read-backs"
//   pick_y_not_flipped         objectAtPixel "flips y", "nearest", "radius 0", "random read-backs"
//   no_search_beside           objectAtPixel "nearest", "equally near", "random read-backs"
// GizmoTests.cpp, HistoryTests.cpp and HotReloadTests.cpp test the rest of the
// lab's editor core.

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab11.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace stoa;

namespace {

using Random = stoa::test::Random;

/// A read-back written as the picture looks in the window: rows[0] is the TOP
/// row, one character per pixel, '.' the background and '1'..'9' the values.
StencilReadback fromPicture(const std::vector<std::string>& rows) {
    StencilReadback stencil;
    stencil.height = static_cast<int>(rows.size());
    stencil.width = static_cast<int>(rows.front().size());
    for (int row = stencil.height - 1; row >= 0; --row)   // glReadPixels: bottom row first
        for (char c : rows[static_cast<std::size_t>(row)])
            stencil.values.push_back(c == '.' ? 0 : static_cast<std::uint8_t>(c - '0'));
    return stencil;
}

/// The reference: the pixel itself, else every pixel of the read-back in its
/// own order (bottom row first), the first strictly nearer one within the radius.
int referencePick(const StencilReadback& stencil, glm::ivec2 mouse, int radius) {
    if (mouse.x < 0 || mouse.y < 0 || mouse.x >= stencil.width || mouse.y >= stencil.height) return -1;
    const auto valueAtWindow = [&](int x, int y) {
        return stencil.values[static_cast<std::size_t>(stencil.height - 1 - y) * stencil.width + x];
    };
    if (valueAtWindow(mouse.x, mouse.y) != 0) return valueAtWindow(mouse.x, mouse.y) - 1;
    int best = -1;
    double bestDistance = 0.0;
    for (std::size_t i = 0; i < stencil.values.size(); ++i) {
        if (stencil.values[i] == 0) continue;
        const int x = static_cast<int>(i % stencil.width);
        const int yWindow = stencil.height - 1 - static_cast<int>(i / stencil.width);
        const double distance = std::hypot(double(x - mouse.x), double(yWindow - mouse.y));
        if (distance > radius) continue;
        if (best < 0 || distance < bestDistance) {
            best = stencil.values[i] - 1;
            bestDistance = distance;
        }
    }
    return best;
}

} // namespace

// --- objectAtPixel --------------------------------------------------------------------

TEST_CASE("Lab 11: objectAtPixel flips y: the read-back's first row is the window's bottom one", "[lab11][editor]") {
    // Three rows in the window: value 1 along the top, 2 in the middle, 3 along the bottom.
    const StencilReadback stencil = fromPicture({"1111", "2222", "3333"});
    REQUIRE(stencil.values.front() == 3);   // the helper stores the bottom row first
    for (int x = 0; x < 4; ++x) {
        CHECK(objectAtPixel(stencil, {x, 0}, 0) == 0);
        CHECK(objectAtPixel(stencil, {x, 1}, 0) == 1);
        CHECK(objectAtPixel(stencil, {x, 2}, 0) == 2);
    }
    // An asymmetric picture: one object pixel in the top-right corner.
    const StencilReadback corner = fromPicture({"...5", "....", "....", "...."});
    CHECK(objectAtPixel(corner, {3, 0}, 0) == 4);
    CHECK(objectAtPixel(corner, {3, 3}, 0) == -1);
    CHECK(objectAtPixel(corner, {0, 0}, 0) == -1);
}

TEST_CASE("Lab 11: objectAtPixel: background 0 is -1, value v is the object v - 1", "[lab11][editor]") {
    StencilReadback stencil;
    stencil.width = 4;
    stencil.height = 1;
    stencil.values = {0, 1, 2, 255};
    CHECK(objectAtPixel(stencil, {0, 0}, 0) == -1);
    CHECK(objectAtPixel(stencil, {1, 0}, 0) == 0);
    CHECK(objectAtPixel(stencil, {2, 0}, 0) == 1);
    CHECK(objectAtPixel(stencil, {3, 0}, 0) == 254);
    // The pixel under the mouse is at distance 0: its neighbours do not matter.
    CHECK(objectAtPixel(stencil, {2, 0}, 3) == 1);
    const StencilReadback empty = fromPicture({".....", ".....", "....."});
    CHECK(objectAtPixel(empty, {2, 1}, 8) == -1);
}

TEST_CASE("Lab 11: objectAtPixel takes the nearest object pixel within the radius, by Euclidean distance",
          "[lab11][editor]") {
    // From the mouse at (3, 3): value 2 at (6, 3) is 3 away, value 1 at (5, 5) is
    // sqrt(8) ~ 2.83 away: nearer by Euclid (by Manhattan distance, 4 against 3, it is not).
    const StencilReadback stencil = fromPicture({".......",
                                                 ".......",
                                                 ".......",
                                                 "......2",
                                                 ".......",
                                                 ".....1.",
                                                 "......."});
    CHECK(objectAtPixel(stencil, {3, 3}, 3) == 0);
    CHECK(objectAtPixel(stencil, {3, 3}, 2) == -1);   // sqrt(8) > 2
    // Within the radius exactly: distance 3 with radius 3 counts.
    const StencilReadback single = fromPicture({".......", "......2", "......."});
    CHECK(objectAtPixel(single, {3, 1}, 3) == 1);
    CHECK(objectAtPixel(single, {3, 1}, 2) == -1);
    // Diagonal: (2, 2) away is sqrt(8) ~ 2.83, beyond a radius of 2 though inside the square.
    const StencilReadback diagonal = fromPicture({"....3", ".....", "....."});
    CHECK(objectAtPixel(diagonal, {2, 2}, 2) == -1);
    CHECK(objectAtPixel(diagonal, {2, 2}, 3) == 2);
    // From the mouse at (0, 4): value 4 at (3, 1) is sqrt(18) ~ 4.24 away, value 5 at (4, 4)
    // 4 away: Euclid takes 5 (by the largest coordinate, 3 against 4, it would take 4).
    const StencilReadback square = fromPicture({".....", "...4.", ".....", ".....", "....5"});
    CHECK(objectAtPixel(square, {0, 4}, 5) == 4);
}

TEST_CASE("Lab 11: objectAtPixel: of equally near pixels, the first in the read-back's order wins", "[lab11][editor]") {
    // Above and below the mouse, both 1 away: the read-back starts at the bottom,
    // so the one below (in the window) comes first.
    const StencilReadback vertical = fromPicture({".1.", "...", ".2."});
    CHECK(objectAtPixel(vertical, {1, 1}, 1) == 1);
    // Left and right in one row: left to right, the left one.
    const StencilReadback horizontal = fromPicture({"3.4"});
    CHECK(objectAtPixel(horizontal, {1, 0}, 1) == 2);
    // Four diagonal neighbours: the bottom-left one.
    const StencilReadback diagonals = fromPicture({"5.6", "...", "7.8"});
    CHECK(objectAtPixel(diagonals, {1, 1}, 2) == 6);
}

TEST_CASE("Lab 11: objectAtPixel with radius 0 reads the pixel only", "[lab11][editor]") {
    const StencilReadback stencil = fromPicture({"1.2", "...", "3.4"});
    CHECK(objectAtPixel(stencil, {1, 1}, 0) == -1);
    CHECK(objectAtPixel(stencil, {1, 0}, 0) == -1);
    CHECK(objectAtPixel(stencil, {0, 0}, 0) == 0);
    CHECK(objectAtPixel(stencil, {2, 2}, 0) == 3);
}

TEST_CASE("Lab 11: objectAtPixel picks nothing outside the read-back", "[lab11][editor]") {
    const StencilReadback stencil = fromPicture({"111", "111"});
    for (const glm::ivec2 mouse : {glm::ivec2(-1, 0), glm::ivec2(0, -1), glm::ivec2(3, 0), glm::ivec2(0, 2),
                                   glm::ivec2(3, 2), glm::ivec2(-5, -5), glm::ivec2(100, 1)})
        for (int radius : {0, 1, 4, 8}) {
            INFO("mouse (" << mouse.x << ", " << mouse.y << ") radius " << radius);
            CHECK(objectAtPixel(stencil, mouse, radius) == -1);
        }
}

TEST_CASE("Lab 11: objectAtPixel agrees with a scan of every pixel on 3,000 random read-backs", "[lab11][editor]") {
    Random random(1101);
    int found = 0, searched = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        StencilReadback stencil;
        stencil.width = 1 + random.below(14);
        stencil.height = 1 + random.below(11);
        const float filled = random.uniform(0.0f, 0.3f);
        for (int i = 0; i < stencil.width * stencil.height; ++i)
            stencil.values.push_back(random.chance(filled) ? static_cast<std::uint8_t>(1 + random.below(255)) : 0);
        const glm::ivec2 mouse(random.below(stencil.width + 4) - 2, random.below(stencil.height + 4) - 2);
        const int radius = random.below(7);
        const int expected = referencePick(stencil, mouse, radius);
        INFO("trial " << trial << ": " << stencil.width << " x " << stencil.height << ", mouse (" << mouse.x << ", "
                      << mouse.y << "), radius " << radius);
        REQUIRE(objectAtPixel(stencil, mouse, radius) == expected);
        if (expected >= 0) ++found;
        if (expected >= 0 && referencePick(stencil, mouse, 0) < 0) ++searched;
    }
    // The random cases cover both kinds of pick.
    CHECK(found > 500);
    CHECK(searched > 300);
}
