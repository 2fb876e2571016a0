// Lab 06's property checks; see checks.hpp. Every object of the field turns
// about Y only, and a turn about Y leaves the Y axis where it was: a stretch
// along Y then shows in a row of the model matrix as well as in a column. A
// turn about X moves it, and only the columns still say how far it reaches.

#include "checks.hpp"
#include "lab06.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

namespace lab06 {

stoa::CheckResult checkSphereTurnedAboutX() {
    // A column 3 times as tall as it is wide, turned 40 degrees about X and moved;
    // then the same stretched along X and along Z instead: any column may be the longest.
    const char* const axisNames[3] = {"X", "Y", "Z"};
    for (const int stretched : {1, 0, 2}) {
        glm::vec3 stretch(1.0f);
        stretch[stretched] = 3.0f;
        const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(4.0f, 1.0f, -6.0f)) *
                                glm::rotate(glm::mat4(1.0f), glm::radians(40.0f), glm::vec3(1.0f, 0.0f, 0.0f)) *
                                glm::scale(glm::mat4(1.0f), stretch);
        const stoa::BoundingSphere local{glm::vec3(0.0f, 0.5f, 0.0f), 1.0f};
        const stoa::BoundingSphere world = stoa::worldBoundingSphere(local, model);
        const std::string what = "worldBoundingSphere() of a sphere of radius 1 under a model that stretches " +
                                 std::string(axisNames[stretched]) + " by 3 and turns 40 degrees about X";

        const glm::vec3 centre(model * glm::vec4(local.center, 1.0f));
        if (glm::length(world.center - centre) > 1e-3f)
            return stoa::CheckResult::fail(what + ": the centre is " + stoa::checkVector(world.center) + ", expected " +
                                           stoa::checkVector(centre) + ", the object's centre carried by the whole model matrix "
                                           "(docs: A sphere in world space)");

        // The points of the object's sphere along its axes and diagonals: each must land inside.
        for (int x = -1; x <= 1; ++x)
            for (int y = -1; y <= 1; ++y)
                for (int z = -1; z <= 1; ++z) {
                    if (x == 0 && y == 0 && z == 0) continue;
                    const glm::vec3 onSphere = local.center + local.radius * glm::normalize(glm::vec3(x, y, z));
                    const glm::vec3 landed(model * glm::vec4(onSphere, 1.0f));
                    const float distance = glm::length(landed - world.center);
                    if (distance > world.radius + 1e-3f)
                        return stoa::CheckResult::fail(
                            what + ": its radius is " + stoa::checkNumber(world.radius, 3) + ", but the point " + stoa::checkVector(onSphere) +
                            " of the object's sphere lands " + stoa::checkNumber(distance, 3) +
                            " from the centre, outside it. The radius grows by the longest column of the model's upper "
                            "3 x 3, how far one step along an object axis goes (docs: A sphere in world space)");
                }
        if (world.radius > 3.0f * 1.001f)
            return stoa::CheckResult::fail(what + ": its radius is " + stoa::checkNumber(world.radius, 3) +
                                           ", larger than needed: the longest column is 3 long, so 3 holds the object "
                                           "(docs: A sphere in world space)");
    }
    return stoa::CheckResult::pass("a sphere stretched along Y (then X, then Z) and turned about X still holds every "
                                   "point of the object's sphere, and is no larger than the longest column says");
}

namespace {

const char* const kSideNames[6] = {"left", "right", "bottom", "top", "near", "far"};

// How far inside side `side` of the clip volume the normalized device point is
// (positive inside): x >= -1 is the left side, x <= 1 the right, and so on.
float insideBy(const glm::vec3& ndc, int side) {
    const float coordinate = ndc[side / 2];
    return side % 2 == 0 ? coordinate + 1.0f : 1.0f - coordinate;
}

} // namespace

stoa::CheckResult checkPlanesBoundClipSpace() {
    // A camera looking down and sideways from off the origin, with a wide aspect.
    const glm::mat4 projection = glm::perspective(glm::radians(55.0f), 1.7f, 0.4f, 60.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(3.0f, 5.0f, 9.0f), glm::vec3(-2.0f, 0.5f, -4.0f),
                                       glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 viewProjection = projection * view;
    const glm::mat4 back = glm::inverse(viewProjection);
    // Guard values right after the six planes: a loop that writes a seventh plane
    // lands on them (the result is built in place, C++17's guaranteed elision).
    struct Guarded {
        stoa::Frustum frustum;
        float guard[8];
    };
    const Guarded guarded{stoa::frustumPlanes(viewProjection), {1, 2, 3, 4, 5, 6, 7, 8}};
    const stoa::Frustum& frustum = guarded.frustum;
    for (int i = 0; i < 8; ++i)
        if (guarded.guard[i] != static_cast<float>(i + 1))
            return stoa::CheckResult::fail("frustumPlanes() wrote past its six planes: a frustum has planes[0] to "
                                           "planes[5], left, right, bottom, top, near, far (docs: The frustum's planes)");
    for (int side = 0; side < 6; ++side) {
        const float length = glm::length(frustum.planes[side].normal);
        if (std::fabs(length - 1.0f) > 1e-3f)
            return stoa::CheckResult::fail("frustumPlanes(): the " + std::string(kSideNames[side]) + " plane's normal is " +
                                           stoa::checkNumber(length, 3) + " long; divide n and d by |n| "
                                           "(docs: The frustum's planes)");
    }
    // Points in and around the clip volume, carried back to the world: each
    // plane must say inside exactly where its side of the volume does.
    stoa::CheckRandom random(20261129u);
    int tried = 0;
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 ndc(2.6f * random.next() - 1.3f, 2.6f * random.next() - 1.3f, 2.2f * random.next() - 1.1f);
        const glm::vec4 carried = back * glm::vec4(ndc, 1.0f);
        if (carried.w <= 0.0f) continue;   // z past the limit of depth: a point behind the eye
        const glm::vec3 world = glm::vec3(carried) / carried.w;
        for (int side = 0; side < 6; ++side) {
            const float expected = insideBy(ndc, side);
            if (std::fabs(expected) < 0.02f) continue;   // too close to the side to judge in floats
            ++tried;
            const stoa::Plane& plane = frustum.planes[side];
            const float distance = glm::dot(plane.normal, world) + plane.d;
            if ((distance >= 0.0f) != (expected > 0.0f))
                return stoa::CheckResult::fail(
                    "frustumPlanes(): the point " + stoa::checkVector(world) + " is " +
                    (expected > 0.0f ? "inside" : "outside") + " the " + kSideNames[side] +
                    " side of the view volume, but the " + kSideNames[side] + " plane puts it " +
                    (expected > 0.0f ? "outside" : "inside") + " (distance " + stoa::checkNumber(distance, 3) +
                    "). Each plane is row 3 plus or minus one other row of projection * view, in the order "
                    "left, right, bottom, top, near, far (docs: The frustum's planes)");
        }
    }
    return stoa::CheckResult::pass("frustumPlanes() of a camera looking down and sideways: six unit normals, and each "
                                   "plane agrees with its side of the view volume on " + std::to_string(tried) +
                                   " points in and around it");
}

stoa::CheckResult checkLevelsOfDetail() {
    struct Expected {
        float quality;
        int levels;
        int level;
    };
    // The page's table for four levels, its ends, and other level counts.
    const Expected table[] = {{1.0f, 4, 0},  {0.76f, 4, 0}, {0.75f, 4, 1}, {0.5f, 4, 2},  {0.26f, 4, 2},
                              {0.25f, 4, 3}, {1e-6f, 4, 3}, {0.0f, 4, -1}, {-0.5f, 4, -1}, {1.0f, 1, 0},
                              {0.01f, 1, 0}, {0.0f, 1, -1}, {0.5f, 5, 2},  {0.59f, 5, 2}, {0.01f, 7, 6},
                              {1e-9f, 4, 3}};
    for (const Expected& row : table) {
        const int level = stoa::levelOfDetail(row.quality, row.levels);
        if (level != row.level)
            return stoa::CheckResult::fail("levelOfDetail(" + stoa::checkNumber(row.quality, 6) + ", " +
                                           std::to_string(row.levels) + ") is " + std::to_string(level) + ", expected " +
                                           std::to_string(row.level) +
                                           (row.level < 0 ? " (not drawn: -1 whenever q <= 0)"
                                                          : " (min(floor((1 - q) n), n - 1))") +
                                           " (docs: Level of detail)");
    }
    // The eye inside the sphere, or on it: q = 1, even where the projected size,
    // on a picture 8 pixels high, would say less.
    const stoa::BoundingSphere sphere{glm::vec3(1.0f, 2.0f, -3.0f), 2.0f};
    const glm::vec3 eyes[] = {{1.0f, 2.0f, -3.0f}, {1.5f, 2.5f, -3.5f}, {3.0f, 2.0f, -3.0f}};
    for (const glm::vec3& eye : eyes) {
        const float quality = stoa::lodQuality(sphere, eye, 60.0f, 8, stoa::LodSettings{});
        if (quality != 1.0f)
            return stoa::CheckResult::fail("lodQuality() of a sphere of radius 2 with the eye " +
                                           stoa::checkNumber(glm::length(eye - sphere.center), 3) +
                                           " from its centre, on a picture 8 pixels high, is " +
                                           stoa::checkNumber(quality, 4) + ": the eye is inside the sphere or on "
                                           "it (d <= r), so q = 1 (docs: Level of detail)");
    }
    return stoa::CheckResult::pass("levelOfDetail() gives the page's levels for 16 qualities and level counts, "
                                   "-1 for q <= 0; lodQuality() is 1 with the eye inside the sphere or on it");
}

stoa::CheckResult checkInsideAtTheBoundary() {
    // The box [-1, 1]^3 as six planes, normals inwards: s(p) = n . p + d.
    stoa::Frustum cube;
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int side = 0; side < 6; ++side) cube.planes[side] = {normals[side], 1.0f};
    for (int side = 0; side < 6; ++side) {
        const glm::vec3 out = -normals[side];   // away from the cube through this side
        const std::string where = std::string(kSideNames[side]) + " side";
        // A sphere of radius 2 whose centre is 3 outside the centre: it touches the side.
        const stoa::BoundingSphere touching{out * 3.0f, 2.0f}, apart{out * 3.0f, 1.75f};
        if (!stoa::sphereInFrustum(cube, touching))
            return stoa::CheckResult::fail("sphereInFrustum() culls a sphere that touches the " + where +
                                           " of the box [-1, 1]^3 from outside (s(c) = -r exactly); it is culled "
                                           "only when s(c) < -r (docs: Is it inside?)");
        if (stoa::sphereInFrustum(cube, apart))
            return stoa::CheckResult::fail("sphereInFrustum() keeps a sphere a quarter outside the " + where +
                                           " of the box [-1, 1]^3 (docs: Is it inside?)");
        // A box from the side outwards, its nearest face on the side's plane: kept.
        const glm::vec3 a = out * 1.0f - glm::vec3(0.5f) * (glm::vec3(1.0f) - glm::abs(out));
        const glm::vec3 b = out * 5.0f + glm::vec3(0.5f) * (glm::vec3(1.0f) - glm::abs(out));
        const stoa::Aabb onTheSide{glm::min(a, b), glm::max(a, b)};
        if (!stoa::boxInFrustum(cube, onTheSide))
            return stoa::CheckResult::fail("boxInFrustum() culls a box whose face lies on the " + where +
                                           "'s plane (s(p+) = 0 exactly); it is culled only when s(p+) < 0 "
                                           "(docs: Is it inside?)");
        const stoa::Aabb beyond{onTheSide.min + out * 0.25f, onTheSide.max + out * 0.25f};
        if (stoa::boxInFrustum(cube, beyond))
            return stoa::CheckResult::fail("boxInFrustum() keeps a box a quarter outside the " + where +
                                           " of the box [-1, 1]^3 (docs: Is it inside?)");
    }
    return stoa::CheckResult::pass("a sphere and a box that touch a side from outside are kept, and culled a "
                                   "quarter further out, on all six sides");
}

} // namespace lab06
