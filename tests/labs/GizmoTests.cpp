// Lab 11's move gizmo (labs/11_editor/student/lab11.hpp) against independent
// references written here, in double:
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
//     for an unmoved mouse.
// The planted mistakes of solutions/11_editor/mistakes/ for them each fail cases
// here (checked by applying each one's find/replace to a copy of the solutions),
// and the equivalent closest_point_by_cross_products passes:
//   ray_parameter_not_axis     closestAxisParameter "by hand", "random line pairs", "lengths";
//                              dragAlongAxis "random drags"
//   drag_from_the_axis_origin  dragAlongAxis "random drags", "at the start"
// StencilPickTests.cpp, HistoryTests.cpp and HotReloadTests.cpp test the rest of
// the lab's editor core.

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab11.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

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

} // namespace

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
