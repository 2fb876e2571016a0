// Lab 11's editor core (labs/11_editor/student/lab11.hpp) against independent
// references written here, in double where there is arithmetic:
//   - objectAtPixel on small read-backs made by hand: the window's y flipped
//     (the read-back's first row is the bottom one), background 0 gives -1 and
//     value v the index v - 1, the nearest object pixel within the radius by
//     Euclidean distance, ties to the pixel first in the read-back's order,
//     radius 0, outside the read-back; then against a scan of every pixel in
//     the read-back's order on 3,000 random read-backs, mice and radii;
//   - closestAxisParameter against the minimum of the squared distance between
//     the axis point and the ray's line, a quadratic in s fitted in double
//     through three samples, on 5,000 random line pairs (seeded); nullopt for
//     parallel lines and for a sine of the angle below 1e-3, a value above;
//     the same s whatever the lengths of the directions (and -s for a reversed
//     axis);
//   - dragAlongAxis: on 3,000 random drags seen from a random eye, the object
//     moves along its axis and the point grabbed at the press, moved with it,
//     is the axis point closest to the current ray (the reference's); start
//     returned exactly for a ray parallel to the axis at the press or now, and
//     for an unmoved mouse;
//   - EditHistory on 400 random sequences of perform / undo / redo / endMerge
//     (commands that set one coordinate of one object, with merge keys per
//     object as the editor makes them) against a model that keeps the scene's
//     states before and after each edit: the scene after every step, the undo
//     and redo counts, the labels, a new edit ending redo, merges only while
//     open and only with an equal non-empty key, undo and redo closing a merge;
//   - assetsToReload on a table of scenarios: the debounce boundary (a change
//     exactly debounce seconds ago counts as quiet), changes at or before
//     loadedAt ignored, files no asset uses ignored, every file of an asset
//     counts, the order of `assets` kept, each asset once however many changes.
// The planted mistakes of solutions/11_editor/mistakes/ each fail cases here
// (checked by applying each one's find/replace to a copy of the solutions), and
// the two equivalents pass:
//   background_is_an_object    objectAtPixel "flips y", "value v", "radius 0", "random read-backs"
//   pick_y_not_flipped         objectAtPixel "flips y", "nearest", "radius 0", "random read-backs"
//   no_search_beside           objectAtPixel "nearest", "equally near", "random read-backs"
//   ray_parameter_not_axis     closestAxisParameter "by hand", "random line pairs", "lengths";
//                              dragAlongAxis "random drags"
//   drag_from_the_axis_origin  dragAlongAxis "random drags", "at the start"
//   every_move_its_own_edit    EditHistory "merges", "close a merge", "random sequences"
//   redo_survives_a_new_edit   EditHistory "a new edit ends redo", "random sequences"
//   no_debounce                assetsToReload "table of scenarios", "the clock ticks"
//   first_file_only            assetsToReload "table of scenarios", "the clock ticks"

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab11.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace stoa;

namespace {

using Random = stoa::test::Random;

std::string describe(const glm::vec3& v) {
    std::ostringstream out;
    out.precision(9);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

std::string describe(const Line& line) { return "point " + describe(line.point) + " direction " + describe(line.direction); }

// --- objectAtPixel ------------------------------------------------------------

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

// --- closestAxisParameter -----------------------------------------------------------

struct DVec3 {
    double x, y, z;
};
DVec3 toDouble(const glm::vec3& v) { return {v.x, v.y, v.z}; }
DVec3 operator+(DVec3 a, DVec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
DVec3 operator-(DVec3 a, DVec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
DVec3 operator*(double s, DVec3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(DVec3 a, DVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(DVec3 a) { return std::sqrt(dot(a, a)); }
DVec3 unit(DVec3 a) { return (1.0 / length(a)) * a; }

/// The squared distance from the axis point at parameter s (along the unit
/// axis direction) to the mouse ray's line, in double.
double squaredDistanceToRay(const Line& ray, const Line& axis, double s) {
    const DVec3 d = unit(toDouble(ray.direction));
    const DVec3 onAxis = toDouble(axis.point) + s * unit(toDouble(axis.direction));
    const DVec3 w = onAxis - toDouble(ray.point);
    const DVec3 across = w - dot(w, d) * d;
    return dot(across, across);
}

/// The reference s: the squared distance is a quadratic A s^2 + B s + C in s
/// (A = the squared sine of the angle between the lines), so three samples
/// give it exactly; its minimum is at -B / 2A.
double referenceParameter(const Line& ray, const Line& axis) {
    const double minus = squaredDistanceToRay(ray, axis, -1.0);
    const double zero = squaredDistanceToRay(ray, axis, 0.0);
    const double plus = squaredDistanceToRay(ray, axis, 1.0);
    const double a = 0.5 * (plus + minus) - zero;
    const double b = 0.5 * (plus - minus);
    return -b / (2.0 * a);
}

constexpr double kUlpsAllowed = 32.0;

double sineBetween(const glm::vec3& a, const glm::vec3& b) {
    const DVec3 u = unit(toDouble(a)), v = unit(toDouble(b));
    const double c = dot(u, v);
    return std::sqrt(std::max(0.0, 1.0 - c * c));
}

/// How far s may be off in float: a few ulps of the points' offset w and of
/// s itself (through the rounding of d . e), divided by the squared sine, the
/// conditioning of the 2 x 2 system.
double parameterTolerance(const Line& ray, const Line& axis) {
    const double w = length(toDouble(ray.point) - toDouble(axis.point));
    const double s = std::abs(referenceParameter(ray, axis));
    const double sine = sineBetween(ray.direction, axis.direction);
    return kUlpsAllowed * 6e-8 * (1.0 + w + s) / (sine * sine);
}

/// A random line through the box [-10, 10]^3 with a direction of random length.
Line randomLine(Random& random) {
    Line line;
    line.point = random.inBox(glm::vec3(-10.0f), glm::vec3(10.0f));
    line.direction = random.unitVector() * random.uniform(0.05f, 20.0f);
    return line;
}

/// The unit direction rotated away from itself by an angle whose sine is `sine`.
glm::vec3 tiltedBy(const glm::vec3& direction, const glm::vec3& across, float sine) {
    const glm::vec3 d = glm::normalize(direction);
    const glm::vec3 side = glm::normalize(across - glm::dot(across, d) * d);
    return std::sqrt(1.0f - sine * sine) * d + sine * side;
}

// --- EditHistory ----------------------------------------------------------------------

/// The scene the history tests edit: three objects; an edit sets one
/// coordinate (x) of one of them, as the editor's move does.
EditorScene threeObjects() {
    EditorScene scene;
    scene.materials.push_back(EditorMaterial{});
    for (const char* name : {"a", "b", "c"}) scene.addObject(name, "shape:cube", scene.materials.front().name);
    return scene;
}

using State = std::vector<float>;   // each object's x, in the scene's order

State stateOf(const EditorScene& scene) {
    State state;
    for (const EditorObject& object : scene.objects) state.push_back(object.position.x);
    return state;
}

/// The command the editor would make to set object `index`'s x to `value`,
/// its revert the value now (when the command is made). Keyed commands are
/// moves, merged per object ("move 2"); unkeyed ones are other edits.
EditCommand setX(const EditorScene& scene, std::size_t index, float value, bool keyed) {
    const std::uint32_t id = scene.objects[index].id;
    const float before = scene.objects[index].position.x;
    const std::string name = scene.objects[index].name;
    return {keyed ? "move " + name : "set " + name,
            [id, value](EditorScene& s) { s.findObject(id)->position.x = value; },
            [id, before](EditorScene& s) { s.findObject(id)->position.x = before; },
            keyed ? "move " + std::to_string(id) : ""};
}

/// The model: every edit as the scene's states before and after it.
struct ModelEdit {
    State before, after;
    std::string label, key;
};

enum class Merge { Closed, Open, Unknown };

struct ModelHistory {
    State scene;
    std::vector<ModelEdit> done, undone;
    // Whether a merge is open. After an undo or a redo that had nothing to do
    // while a merge was open, the contract ("nothing changes") and the
    // equivalent solution that closes the merge anyway disagree: Unknown, and
    // the sequences below close it before a command that could merge.
    Merge merge = Merge::Closed;
};

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

// --- closestAxisParameter -----------------------------------------------------------------

TEST_CASE("Lab 11: closestAxisParameter on lines by hand", "[lab11][editor]") {
    // The x axis through (1, 0, 0), a ray down -z through (3, 2, 5): closest at x = 3, s = 2.
    const Line axis{{1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    const Line ray{{3.0f, 2.0f, 5.0f}, {0.0f, 0.0f, -1.0f}};
    const std::optional<float> s = closestAxisParameter(ray, axis);
    REQUIRE(s);
    CHECK(std::abs(*s - 2.0f) <= 1e-6f);
    // The axis the other way: the same point is at s = -2.
    const std::optional<float> reversed = closestAxisParameter(ray, Line{axis.point, -axis.direction});
    REQUIRE(reversed);
    CHECK(std::abs(*reversed + 2.0f) <= 1e-6f);
    // Intersecting lines: the intersection. The y axis at the origin, a ray at 45 degrees through (0, 3, 0).
    const std::optional<float> crossing =
        closestAxisParameter(Line{{-3.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}}, Line{glm::vec3(0.0f), {0.0f, 1.0f, 0.0f}});
    REQUIRE(crossing);
    CHECK(std::abs(*crossing - 3.0f) <= 1e-5f);
}

TEST_CASE("Lab 11: closestAxisParameter agrees with the minimum distance in double on 5,000 random line pairs",
          "[lab11][editor]") {
    Random random(1102);
    double worst = 0.0;
    int compared = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const Line ray = randomLine(random);
        const Line axis = randomLine(random);
        const double sine = sineBetween(ray.direction, axis.direction);
        const std::optional<float> s = closestAxisParameter(ray, axis);
        INFO("trial " << trial << ": ray " << describe(ray) << ", axis " << describe(axis) << ", sine " << sine);
        if (sine < 2e-3) continue;   // near the 1e-3 threshold: see the nearly-parallel case
        REQUIRE(s);
        const double expected = referenceParameter(ray, axis);
        const double error = std::abs(*s - expected) / parameterTolerance(ray, axis);
        INFO("s " << *s << ", expected " << expected);
        REQUIRE(error <= 1.0);
        // And no nearby s brings the lines closer (beyond rounding).
        const double at = squaredDistanceToRay(ray, axis, *s);
        const double step = 1e-2 * (1.0 + std::abs(expected));
        CHECK(at <= squaredDistanceToRay(ray, axis, *s + step) + 1e-9 * (1.0 + at));
        CHECK(at <= squaredDistanceToRay(ray, axis, *s - step) + 1e-9 * (1.0 + at));
        worst = std::max(worst, error);
        ++compared;
    }
    CHECK(compared > 4900);
    INFO("the largest error, as a fraction of the tolerance: " << worst);
    CHECK(worst < 1.0);
}

TEST_CASE("Lab 11: closestAxisParameter gives nullopt for parallel and nearly parallel lines", "[lab11][editor]") {
    Random random(1103);
    for (int trial = 0; trial < 500; ++trial) {
        const Line axis = randomLine(random);
        const glm::vec3 across = random.unitVector();
        const Line parallel{random.inBox(glm::vec3(-10.0f), glm::vec3(10.0f)),
                            (random.chance(0.5f) ? 1.0f : -1.0f) * random.uniform(0.1f, 10.0f) * axis.direction};
        INFO("trial " << trial << ": axis " << describe(axis) << ", ray " << describe(parallel));
        CHECK_FALSE(closestAxisParameter(parallel, axis));
        // A sine of 1e-4 and 5e-4: below the 1e-3 of the contract.
        for (float sine : {1e-4f, 5e-4f}) {
            const Line nearly{parallel.point, tiltedBy(axis.direction, across, sine) * random.uniform(0.1f, 10.0f)};
            INFO("sine " << sineBetween(nearly.direction, axis.direction));
            CHECK_FALSE(closestAxisParameter(nearly, axis));
        }
        // A sine of 1e-2: well above it, there is a closest point.
        const Line tilted{parallel.point, tiltedBy(axis.direction, across, 1e-2f)};
        CHECK(closestAxisParameter(tilted, axis));
    }
    // The same line as the axis.
    const Line axis{{1.0f, 2.0f, 3.0f}, {0.0f, 1.0f, 0.0f}};
    CHECK_FALSE(closestAxisParameter(axis, axis));
}

TEST_CASE("Lab 11: closestAxisParameter does not depend on the lengths of the directions", "[lab11][editor]") {
    Random random(1104);
    for (int trial = 0; trial < 1000; ++trial) {
        const Line ray = randomLine(random);
        const Line axis = randomLine(random);
        if (sineBetween(ray.direction, axis.direction) < 0.05) continue;
        const std::optional<float> s = closestAxisParameter(ray, axis);
        REQUIRE(s);
        const double tolerance = parameterTolerance(ray, axis);
        const float rayScale = random.uniform(0.01f, 100.0f);
        const float axisScale = random.uniform(0.01f, 100.0f);
        INFO("trial " << trial << ": ray " << describe(ray) << ", axis " << describe(axis) << ", scales " << rayScale
                      << " and " << axisScale);
        const std::optional<float> scaled =
            closestAxisParameter(Line{ray.point, ray.direction * rayScale}, Line{axis.point, axis.direction * axisScale});
        REQUIRE(scaled);
        CHECK(std::abs(*scaled - *s) <= tolerance);
        // The ray reversed: the same line, the same s; the axis reversed: s counts the other way.
        const std::optional<float> rayReversed = closestAxisParameter(Line{ray.point, -ray.direction}, axis);
        REQUIRE(rayReversed);
        CHECK(std::abs(*rayReversed - *s) <= tolerance);
        const std::optional<float> axisReversed = closestAxisParameter(ray, Line{axis.point, -axis.direction * axisScale});
        REQUIRE(axisReversed);
        CHECK(std::abs(*axisReversed + *s) <= tolerance);
    }
}

// --- dragAlongAxis ----------------------------------------------------------------------

TEST_CASE("Lab 11: dragAlongAxis keeps the point grabbed under the mouse on 3,000 random drags", "[lab11][editor]") {
    Random random(1105);
    int compared = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        // An object, one of its gizmo's axes (the world's, or any direction, of any length),
        // and an eye looking at points near the object through the press and the current mouse.
        const glm::vec3 start = random.inBox(glm::vec3(-5.0f), glm::vec3(5.0f));
        glm::vec3 axisDirection(0.0f);
        if (random.chance(0.5f))
            axisDirection[random.below(3)] = random.chance(0.5f) ? 1.0f : -1.0f;
        else
            axisDirection = random.unitVector() * random.uniform(0.1f, 5.0f);
        const glm::vec3 eye = start + random.unitVector() * random.uniform(3.0f, 20.0f);
        const glm::vec3 pressTarget = start + random.inBox(glm::vec3(-1.0f), glm::vec3(1.0f));
        const glm::vec3 currentTarget = pressTarget + random.inBox(glm::vec3(-3.0f), glm::vec3(3.0f));
        const Line pressRay{eye, (pressTarget - eye) * random.uniform(0.1f, 3.0f)};
        const Line currentRay{eye, (currentTarget - eye) * random.uniform(0.1f, 3.0f)};
        const Line axis{start, axisDirection};
        const double pressSine = sineBetween(pressRay.direction, axisDirection);
        const double currentSine = sineBetween(currentRay.direction, axisDirection);
        if (pressSine < 0.05 || currentSine < 0.05) continue;

        const glm::vec3 moved = dragAlongAxis(start, axisDirection, pressRay, currentRay);
        // The grabbed point (closest to the press ray on the axis), moved with the object,
        // is the axis point closest to the current ray.
        const DVec3 e = unit(toDouble(axisDirection));
        const DVec3 grabbed = toDouble(start) + referenceParameter(pressRay, axis) * e;
        const DVec3 expected = toDouble(start) + referenceParameter(currentRay, axis) * e;
        const DVec3 grabbedMoved = grabbed + (toDouble(moved) - toDouble(start));
        const double tolerance = parameterTolerance(pressRay, axis) + parameterTolerance(currentRay, axis) + 1e-5;
        INFO("trial " << trial << ": start " << describe(start) << ", axis " << describe(axisDirection)
                      << ", press ray " << describe(pressRay) << ", current ray " << describe(currentRay)
                      << ", moved to " << describe(moved));
        REQUIRE(length(grabbedMoved - expected) <= tolerance);
        // The object moves along its axis only.
        const DVec3 offset = toDouble(moved) - toDouble(start);
        REQUIRE(length(offset - dot(offset, e) * e) <= 1e-5 * (1.0 + length(offset)));
        ++compared;
    }
    CHECK(compared > 2500);
}

TEST_CASE("Lab 11: dragAlongAxis leaves the object at the start for an unmoved mouse or a ray along the axis",
          "[lab11][editor]") {
    Random random(1106);
    for (int trial = 0; trial < 500; ++trial) {
        const glm::vec3 start = random.inBox(glm::vec3(-5.0f), glm::vec3(5.0f));
        const glm::vec3 axisDirection = random.unitVector() * random.uniform(0.1f, 5.0f);
        const Line ray{start + random.unitVector() * random.uniform(3.0f, 20.0f), random.unitVector()};
        const Line along{random.inBox(glm::vec3(-10.0f), glm::vec3(10.0f)), -axisDirection * random.uniform(0.1f, 5.0f)};
        INFO("trial " << trial << ": start " << describe(start) << ", axis " << describe(axisDirection) << ", ray "
                      << describe(ray));
        if (sineBetween(ray.direction, axisDirection) < 2e-3) continue;
        // The mouse has not moved: the object has not either.
        const glm::vec3 unmoved = dragAlongAxis(start, axisDirection, ray, ray);
        CHECK(glm::length(unmoved - start) <= 1e-5f * (1.0f + glm::length(start)));
        // A ray parallel to the axis, at the press or now: no closest point, the object stays.
        CHECK(dragAlongAxis(start, axisDirection, ray, along) == start);
        CHECK(dragAlongAxis(start, axisDirection, along, ray) == start);
        CHECK(dragAlongAxis(start, axisDirection, along, along) == start);
    }
}

// --- EditHistory ------------------------------------------------------------------------

TEST_CASE("Lab 11: EditHistory undoes and redoes edits in order", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    CHECK_FALSE(history.undo(scene));
    CHECK_FALSE(history.redo(scene));
    history.perform(scene, setX(scene, 0, 1.0f, false));
    history.perform(scene, setX(scene, 1, 2.0f, false));
    history.perform(scene, setX(scene, 0, 3.0f, false));
    CHECK(stateOf(scene) == State{3.0f, 2.0f, 0.0f});
    CHECK(history.undoCount() == 3);
    CHECK(history.doneLabels() == std::vector<std::string>{"set a", "set b", "set a"});
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{1.0f, 2.0f, 0.0f});
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{1.0f, 0.0f, 0.0f});
    CHECK(history.undoCount() == 1);
    CHECK(history.redoCount() == 2);
    REQUIRE(history.redo(scene));
    CHECK(stateOf(scene) == State{1.0f, 2.0f, 0.0f});
    REQUIRE(history.undo(scene));
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
    CHECK_FALSE(history.undo(scene));   // nothing left: nothing changes
    CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
    CHECK(history.redoCount() == 3);
    while (history.redo(scene)) {
    }
    CHECK(stateOf(scene) == State{3.0f, 2.0f, 0.0f});
    CHECK(history.undoCount() == 3);
    CHECK(history.redoCount() == 0);
}

TEST_CASE("Lab 11: EditHistory: a new edit ends redo", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    history.perform(scene, setX(scene, 0, 1.0f, false));
    history.perform(scene, setX(scene, 0, 2.0f, false));
    REQUIRE(history.undo(scene));
    REQUIRE(history.redoCount() == 1);
    history.perform(scene, setX(scene, 1, 5.0f, false));
    CHECK(history.redoCount() == 0);
    CHECK_FALSE(history.redo(scene));
    CHECK(stateOf(scene) == State{1.0f, 5.0f, 0.0f});
    CHECK(history.doneLabels() == std::vector<std::string>{"set a", "set b"});
}

TEST_CASE("Lab 11: EditHistory merges commands with the same key while the merge is open", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    // One drag of a: four moves, one edit.
    for (float x : {1.0f, 2.0f, 3.0f, 4.0f}) history.perform(scene, setX(scene, 0, x, true));
    history.endMerge();
    CHECK(history.undoCount() == 1);
    CHECK(stateOf(scene) == State{4.0f, 0.0f, 0.0f});
    // A second drag of a, after the button went up: a new edit.
    for (float x : {5.0f, 6.0f}) history.perform(scene, setX(scene, 0, x, true));
    CHECK(history.undoCount() == 2);
    // A move of b: another key, another edit; then a again: not the latest key, another edit.
    history.perform(scene, setX(scene, 1, 7.0f, true));
    history.perform(scene, setX(scene, 0, 8.0f, true));
    CHECK(history.undoCount() == 4);
    history.endMerge();
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{6.0f, 7.0f, 0.0f});
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{6.0f, 0.0f, 0.0f});
    REQUIRE(history.undo(scene));   // the whole second drag
    CHECK(stateOf(scene) == State{4.0f, 0.0f, 0.0f});
    REQUIRE(history.undo(scene));   // the whole first drag
    CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
    // Redo brings the whole drag back, at its last move.
    REQUIRE(history.redo(scene));
    CHECK(stateOf(scene) == State{4.0f, 0.0f, 0.0f});

    // Empty keys never merge, even back to back.
    EditorScene plain = threeObjects();
    EditHistory unkeyed;
    for (float x : {1.0f, 2.0f, 3.0f}) unkeyed.perform(plain, setX(plain, 2, x, false));
    CHECK(unkeyed.undoCount() == 3);
    // An unkeyed edit between two moves of a closes the merge.
    unkeyed.perform(plain, setX(plain, 0, 1.0f, true));
    unkeyed.perform(plain, setX(plain, 1, 1.0f, false));
    unkeyed.perform(plain, setX(plain, 0, 2.0f, true));
    CHECK(unkeyed.undoCount() == 6);
}

TEST_CASE("Lab 11: EditHistory: undo and redo close a merge", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    history.perform(scene, setX(scene, 0, 1.0f, false));
    history.perform(scene, setX(scene, 0, 2.0f, true));
    history.perform(scene, setX(scene, 0, 3.0f, true));
    REQUIRE(history.undoCount() == 2);
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{1.0f, 0.0f, 0.0f});
    // Two moves after the undo: one new edit (the edit before it has no key).
    history.perform(scene, setX(scene, 0, 4.0f, true));
    history.perform(scene, setX(scene, 0, 5.0f, true));
    CHECK(history.undoCount() == 2);
    // Undo, redo: the redone move is not open for merging.
    REQUIRE(history.undo(scene));
    REQUIRE(history.redo(scene));
    CHECK(stateOf(scene) == State{5.0f, 0.0f, 0.0f});
    history.perform(scene, setX(scene, 0, 6.0f, true));
    CHECK(history.undoCount() == 3);
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{5.0f, 0.0f, 0.0f});
    // Undo closes it too: a move (a new edit, the merge open), undone; the next move with
    // the same key as the latest edit (the 5.0 move) is a new edit.
    history.perform(scene, setX(scene, 0, 7.0f, true));
    CHECK(history.undoCount() == 3);
    REQUIRE(history.undo(scene));
    history.perform(scene, setX(scene, 0, 8.0f, true));
    CHECK(history.undoCount() == 3);
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{5.0f, 0.0f, 0.0f});
}

TEST_CASE("Lab 11: EditHistory agrees with a model of scene states on 400 random sequences", "[lab11][editor]") {
    Random random(1107);
    int merged = 0, redoneAfterUndo = 0, redoCleared = 0;
    for (int sequence = 0; sequence < 400; ++sequence) {
        EditorScene scene = threeObjects();
        EditHistory history;
        ModelHistory model;
        model.scene = stateOf(scene);
        std::ostringstream steps;
        const int length = 10 + random.below(50);
        for (int step = 0; step < length; ++step) {
            const int what = random.below(10);
            if (what < 5) {   // perform: an edit of one object, keyed (a move) or not
                const std::size_t index = static_cast<std::size_t>(random.below(3));
                const bool keyed = random.chance(0.7f);
                const float value = static_cast<float>(random.below(1000));
                EditCommand command = setX(scene, index, value, keyed);
                const bool sameKey = !model.done.empty() && keyed && model.done.back().key == command.mergeKey;
                if (model.merge == Merge::Unknown && sameKey) {
                    history.endMerge();
                    model.merge = Merge::Closed;
                    steps << "endMerge; ";
                }
                steps << "perform " << command.label << " x=" << value << "; ";
                ModelEdit edit{model.scene, model.scene, command.label, command.mergeKey};
                edit.after[index] = value;
                if (!model.undone.empty()) ++redoCleared;
                model.undone.clear();
                if (model.merge == Merge::Open && sameKey) {
                    model.done.back().after = edit.after;
                    model.done.back().label = edit.label;
                    ++merged;
                } else {
                    model.done.push_back(edit);
                    model.merge = keyed ? Merge::Open : Merge::Closed;
                }
                model.scene = edit.after;
                history.perform(scene, std::move(command));
            } else if (what < 7) {
                steps << "undo; ";
                const bool expected = !model.done.empty();
                if (expected) {
                    model.scene = model.done.back().before;
                    model.undone.push_back(model.done.back());
                    model.done.pop_back();
                    model.merge = Merge::Closed;
                } else if (model.merge == Merge::Open) {
                    model.merge = Merge::Unknown;
                }
                INFO(steps.str());
                REQUIRE(history.undo(scene) == expected);
            } else if (what < 9) {
                steps << "redo; ";
                const bool expected = !model.undone.empty();
                if (expected) {
                    model.scene = model.undone.back().after;
                    model.done.push_back(model.undone.back());
                    model.undone.pop_back();
                    model.merge = Merge::Closed;
                    ++redoneAfterUndo;
                } else if (model.merge == Merge::Open) {
                    model.merge = Merge::Unknown;
                }
                INFO(steps.str());
                REQUIRE(history.redo(scene) == expected);
            } else {
                steps << "endMerge; ";
                history.endMerge();
                model.merge = Merge::Closed;
            }
            INFO("sequence " << sequence << ": " << steps.str());
            REQUIRE(stateOf(scene) == model.scene);
            REQUIRE(history.undoCount() == model.done.size());
            REQUIRE(history.redoCount() == model.undone.size());
            std::vector<std::string> labels;
            for (const ModelEdit& edit : model.done) labels.push_back(edit.label);
            REQUIRE(history.doneLabels() == labels);
        }
        // Undo everything: the scene as it began; redo everything: as it ended.
        const State end = model.undone.empty() ? model.scene : model.undone.front().after;
        while (history.undo(scene)) {
        }
        CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
        while (history.redo(scene)) {
        }
        CHECK(stateOf(scene) == end);
    }
    // The sequences exercise merges, redo and a new edit after an undo.
    CHECK(merged > 200);
    CHECK(redoneAfterUndo > 200);
    CHECK(redoCleared > 200);
}

// --- assetsToReload -----------------------------------------------------------------------

TEST_CASE("Lab 11: assetsToReload on a table of scenarios", "[lab11][editor]") {
    const std::string diffuse = "/assets/panel_diffuse.png", stripes = "/assets/panel_stripes.png";
    const std::string shader = "/shaders/lit.frag", common = "/shaders/common.glsl", other = "/assets/unrelated.png";
    struct Scenario {
        const char* name;
        std::vector<FileChange> changes;
        std::vector<AssetFiles> assets;
        double now, debounce;
        std::vector<std::string> expected;
    };
    const AssetFiles panel{"panel", {diffuse, stripes}, 0.0};
    const AssetFiles lit{"lit", {shader, common}, 0.0};
    const std::vector<Scenario> scenarios = {
        {"nothing changed", {}, {panel, lit}, 10.0, 0.25, {}},
        {"one change, quiet since", {{diffuse, 1.0}}, {panel}, 2.0, 0.25, {"panel"}},
        {"one change, not yet quiet", {{diffuse, 1.0}}, {panel}, 1.1, 0.25, {}},
        // The debounce boundary: a change exactly debounce seconds ago counts as quiet
        // (latest <= now - debounce); the values are exact in binary.
        {"debounce: exactly quiet", {{diffuse, 1.0}}, {panel}, 1.25, 0.25, {"panel"}},
        {"debounce: just short of quiet", {{diffuse, 1.0}}, {panel}, 1.2499, 0.25, {}},
        {"debounce 0: due at once", {{diffuse, 1.0}}, {panel}, 1.0, 0.0, {"panel"}},
        {"debounce: the latest change of any file counts", {{diffuse, 1.0}, {stripes, 1.5}}, {panel}, 1.6, 0.25, {}},
        {"debounce: an old change of the asset, a later one of an unrelated file", {{diffuse, 1.0}, {other, 1.9}},
         {panel}, 2.0, 0.25, {"panel"}},
        {"changed before it was loaded", {{diffuse, 1.0}}, {{"panel", {diffuse, stripes}, 2.0}}, 5.0, 0.25, {}},
        {"changed exactly when it was loaded", {{diffuse, 2.0}}, {{"panel", {diffuse, stripes}, 2.0}}, 5.0, 0.25, {}},
        {"changed before and after it was loaded", {{diffuse, 1.0}, {stripes, 3.0}},
         {{"panel", {diffuse, stripes}, 2.0}}, 5.0, 0.25, {"panel"}},
        {"a change before loading keeps it from being quiet", {{diffuse, 3.0}, {stripes, 4.9}},
         {{"panel", {diffuse, stripes}, 3.5}}, 5.0, 0.25, {}},
        {"every file of an asset counts: the second", {{stripes, 1.0}}, {panel}, 2.0, 0.25, {"panel"}},
        {"every file of an asset counts: the last of three", {{"/c", 1.0}}, {{"three", {"/a", "/b", "/c"}, 0.0}}, 2.0,
         0.25, {"three"}},
        {"unrelated files ignored", {{other, 1.0}, {"/assets/panel_diffuse.png.tmp", 1.0}}, {panel, lit}, 5.0, 0.25, {}},
        {"the order of assets kept", {{shader, 1.0}, {diffuse, 1.2}}, {panel, lit}, 5.0, 0.25, {"panel", "lit"}},
        {"the order of assets kept, the other way", {{diffuse, 1.0}, {shader, 1.2}}, {lit, panel}, 5.0, 0.25,
         {"lit", "panel"}},
        {"each once, however many changes",
         {{diffuse, 1.0}, {diffuse, 1.01}, {stripes, 1.02}, {diffuse, 1.03}, {stripes, 1.04}, {diffuse, 1.05}},
         {panel},
         5.0,
         0.25,
         {"panel"}},
        {"a file two assets share reloads both", {{common, 1.0}},
         {{"lit", {shader, common}, 0.0}, {"unlit", {"/shaders/unlit.frag", common}, 0.0}, panel}, 5.0, 0.25,
         {"lit", "unlit"}},
        {"one due, one still busy", {{diffuse, 1.0}, {shader, 4.9}}, {panel, lit}, 5.0, 0.25, {"panel"}},
        {"an asset without files", {{diffuse, 1.0}}, {{"empty", {}, 0.0}, panel}, 5.0, 0.25, {"panel"}},
        {"no assets", {{diffuse, 1.0}}, {}, 5.0, 0.25, {}},
    };
    for (const Scenario& scenario : scenarios) {
        INFO(scenario.name);
        CHECK(assetsToReload(scenario.changes, scenario.assets, scenario.now, scenario.debounce) == scenario.expected);
    }
}

TEST_CASE("Lab 11: assetsToReload as the editor's clock ticks: due once quiet, then not again until a new change",
          "[lab11][editor]") {
    // The case reload_when_quiet: saves at 0, 0.2 and 0.6 s, ticks at 0.1 .. 0.7 s.
    const std::string diffuse = "/lab11/panel_diffuse.png", stripes = "/lab11/panel_stripes.png";
    std::vector<FileChange> changes;
    AssetFiles panel{"panel", {diffuse, stripes}, -1.0};
    std::vector<double> reloads;
    const auto tick = [&](double now) {
        const std::vector<std::string> due = assetsToReload(changes, {panel}, now, 0.25);
        if (!due.empty()) {
            CHECK(due == std::vector<std::string>{"panel"});
            panel.loadedAt = now;
            reloads.push_back(now);
        }
    };
    changes.push_back({diffuse, 0.0});
    tick(0.1);
    changes.push_back({stripes, 0.2});
    tick(0.3);
    tick(0.5);
    tick(0.55);   // loaded at 0.5, nothing changed since
    changes.push_back({diffuse, 0.6});
    tick(0.7);
    tick(0.85);
    tick(0.9);
    CHECK(reloads == std::vector<double>{0.5, 0.85});
}
