// Lab 10's key frame functions (labs/10_crowds/student/lab10.hpp) against
// independent references written here, in double:
//   - md2FramesAt against fmod in double: frame k at k / fps, the last frame
//     blending into the animation's own first, seconds past a thousand loops, a
//     one-frame animation, indices offset by animation.first, t in [0, 1) on a
//     sweep and just below loop boundaries, and 5,000 random cases compared as
//     a phase on the loop (so that k - 1 with t near 1 matches k with t near 0);
//   - blendMd2Frames: t = 0 and 1 give the frames, positions the mix in double,
//     normals of unit length along the normalized mix, outputs resized from
//     longer and shorter vectors.
// The planted mistakes of solutions/10_crowds/mistakes/ for these functions each
// fail cases here (checked by applying each one's find/replace to a copy of the solution):
//   no_wrap_to_first_frame     every md2FramesAt case but "one-frame" and "offset"
// and one the lab dropped: normals_not_renormalized (blendMd2Frames "unit length").
// BehaviourTests.cpp tests the lab's machines and layers, GroundTests.cpp its ground.

#include "catch.hpp"
#include "TestRandom.hpp"
#include "lab10.hpp"

#include <stoa/crowd/CrowdLab.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace stoa;

namespace {

// Key frames.

struct ReferencePair {
    int first, second;
    double t;
};

ReferencePair referenceFrames(const Md2Animation& animation, double seconds, double framesPerSecond) {
    double phase = std::fmod(seconds * framesPerSecond, static_cast<double>(animation.count));
    if (phase < 0.0) phase += animation.count;
    const int k = std::min(static_cast<int>(phase), animation.count - 1);
    const int next = k + 1 == animation.count ? 0 : k + 1;
    return {animation.first + k, animation.first + next, phase - k};
}

/// Where on the loop a pair puts the pose, in frames from the animation's
/// first: k + t. Two pairs agree when these are close around the loop.
double loopDistance(const Md2Animation& animation, double a, double b) {
    const double d = std::fmod(std::abs(a - b), static_cast<double>(animation.count));
    return std::min(d, animation.count - d);
}

std::string describe(const Md2FramePair& pair) {
    std::ostringstream out;
    out.precision(9);
    out << "{first " << pair.first << ", second " << pair.second << ", t " << pair.t << "}";
    return out.str();
}

void requireValidPair(const Md2Animation& animation, const Md2FramePair& pair) {
    INFO(describe(pair));
    REQUIRE(pair.first >= animation.first);
    REQUIRE(pair.first < animation.first + animation.count);
    REQUIRE(pair.second == animation.first + (pair.first - animation.first + 1) % animation.count);
    REQUIRE(pair.t >= 0.0f);
    REQUIRE(pair.t < 1.0f);
}

Md2Frame randomFrame(test::Random& random, int vertices) {
    Md2Frame frame;
    for (int i = 0; i < vertices; ++i) {
        frame.positions.push_back(random.inBox(glm::vec3(-20.0f), glm::vec3(20.0f)));
        frame.normals.push_back(random.unitVector());
    }
    return frame;
}

double distance(const glm::vec3& a, const glm::dvec3& b) { return glm::length(glm::dvec3(a) - b); }

} // namespace

// md2FramesAt

TEST_CASE("Lab 10: md2FramesAt shows frame k at k / fps seconds", "[lab10][crowds]") {
    const Md2Animation run{"run", 10, 6};
    for (int k = 0; k < 6; ++k) {
        const Md2FramePair pair = md2FramesAt(run, static_cast<float>(k) / 8.0f, 8.0f);
        INFO("k " << k << ": " << describe(pair));
        CHECK(pair.first == 10 + k);
        CHECK(pair.second == 10 + (k + 1) % 6);
        CHECK(pair.t == 0.0f);
    }
    // At 10 frames per second k / 10 is not exact in float: frame k, or k - 1 with t near 1.
    for (int k = 0; k < 6; ++k) {
        const Md2FramePair pair = md2FramesAt(run, static_cast<float>(k) / 10.0f, 10.0f);
        INFO("k " << k << ": " << describe(pair));
        requireValidPair(run, pair);
        CHECK(loopDistance(run, pair.first - run.first + pair.t, k) < 1e-5);
    }
    const Md2FramePair between = md2FramesAt(run, 2.5f / 8.0f, 8.0f);
    CHECK(between.first == 12);
    CHECK(between.second == 13);
    CHECK(between.t == Approx(0.5));
}

TEST_CASE("Lab 10: md2FramesAt: the last frame blends into the animation's own first", "[lab10][crowds]") {
    const Md2Animation run{"run", 10, 6};
    const Md2FramePair pair = md2FramesAt(run, 5.5f / 8.0f, 8.0f);
    INFO(describe(pair));
    CHECK(pair.first == 15);
    CHECK(pair.second == 10);
    CHECK(pair.t == Approx(0.5));
    const Md2FramePair loop = md2FramesAt(run, 6.0f / 8.0f, 8.0f);   // a whole loop: frame 0 again
    CHECK(loop.first == 10);
    CHECK(loop.second == 11);
    CHECK(loop.t == 0.0f);
}

TEST_CASE("Lab 10: md2FramesAt after a thousand loops", "[lab10][crowds]") {
    const Md2Animation run{"run", 10, 6};
    // (6000 + 2.25) / 8 = 750.28125 s, exact in float.
    const Md2FramePair pair = md2FramesAt(run, 750.28125f, 8.0f);
    INFO(describe(pair));
    CHECK(pair.first == 12);
    CHECK(pair.second == 13);
    CHECK(pair.t == Approx(0.25));
    const Md2FramePair last = md2FramesAt(run, (5994.0f + 5.75f) / 8.0f, 8.0f);
    INFO(describe(last));
    CHECK(last.first == 15);
    CHECK(last.second == 10);
    CHECK(last.t == Approx(0.75));
}

TEST_CASE("Lab 10: md2FramesAt on a one-frame animation stays on it", "[lab10][crowds]") {
    const Md2Animation pose{"pose", 3, 1};
    for (const float seconds : {0.0f, 0.01f, 0.125f, 0.3f, 1.0f, 17.77f, 1234.5f}) {
        const Md2FramePair pair = md2FramesAt(pose, seconds, 8.0f);
        INFO("at " << seconds << " s: " << describe(pair));
        CHECK(pair.first == 3);
        CHECK(pair.second == 3);
        CHECK(pair.t >= 0.0f);
        CHECK(pair.t < 1.0f);
    }
}

TEST_CASE("Lab 10: md2FramesAt's indices are offset by animation.first", "[lab10][crowds]") {
    for (const float seconds : {0.0f, 0.2f, 0.61f, 0.99f, 3.3f}) {
        const Md2FramePair atZero = md2FramesAt({"a", 0, 5}, seconds, 9.0f);
        const Md2FramePair atForty = md2FramesAt({"b", 40, 5}, seconds, 9.0f);
        INFO("at " << seconds << " s: " << describe(atZero) << " and " << describe(atForty));
        CHECK(atForty.first == atZero.first + 40);
        CHECK(atForty.second == atZero.second + 40);
        CHECK(atForty.t == atZero.t);
        CHECK(atForty.first >= 40);
        CHECK(atForty.first < 45);
    }
}

TEST_CASE("Lab 10: md2FramesAt's t is at least 0 and below 1, also just below a loop's end", "[lab10][crowds]") {
    const Md2Animation run{"run", 7, 6};
    for (int i = 0; i < 20000; ++i) requireValidPair(run, md2FramesAt(run, static_cast<float>(i) * 0.00731f, 8.0f));
    for (int loops = 1; loops < 2000; loops += 37) {
        for (const float fps : {8.0f, 9.0f, 10.0f, 24.0f}) {
            const float end = static_cast<float>(loops) * 6.0f / fps;
            const float below = std::nextafter(end, 0.0f);
            INFO(loops << " loops at " << fps << " fps, " << below << " s");
            requireValidPair(run, md2FramesAt(run, below, fps));
            requireValidPair(run, md2FramesAt(run, end, fps));
        }
    }
}

TEST_CASE("Lab 10: md2FramesAt agrees with the reference on 5,000 random cases", "[lab10][crowds]") {
    test::Random random(8080);
    for (int i = 0; i < 5000; ++i) {
        const Md2Animation animation{"x", random.below(200), 1 + random.below(40)};
        const float fps = random.uniform(1.0f, 30.0f);
        const float seconds = random.uniform(0.0f, 500.0f);
        const Md2FramePair pair = md2FramesAt(animation, seconds, fps);
        const ReferencePair want = referenceFrames(animation, seconds, fps);
        INFO("animation first " << animation.first << " count " << animation.count << ", " << seconds << " s at "
                                << fps << " fps: " << describe(pair) << ", want first " << want.first << " t "
                                << want.t);
        requireValidPair(animation, pair);
        // float's product seconds * fps is off by up to about 1e-7 of it.
        const double tolerance = 4e-7 * seconds * fps + 1e-6;
        REQUIRE(loopDistance(animation, pair.first - animation.first + pair.t, want.first - animation.first + want.t) <
                tolerance);
    }
}

// blendMd2Frames

TEST_CASE("Lab 10: blendMd2Frames at t = 0 and t = 1 gives the frames", "[lab10][crowds]") {
    test::Random random(9090);
    const Md2Frame a = randomFrame(random, 60), b = randomFrame(random, 60);
    std::vector<glm::vec3> positions, normals;
    blendMd2Frames(a, b, 0.0f, positions, normals);
    REQUIRE(positions.size() == 60);
    REQUIRE(normals.size() == 60);
    for (std::size_t i = 0; i < 60; ++i) {
        CHECK(distance(positions[i], glm::dvec3(a.positions[i])) < 1e-5);
        CHECK(distance(normals[i], glm::dvec3(a.normals[i])) < 1e-5);
    }
    blendMd2Frames(a, b, 1.0f, positions, normals);
    for (std::size_t i = 0; i < 60; ++i) {
        CHECK(distance(positions[i], glm::dvec3(b.positions[i])) < 1e-5);
        CHECK(distance(normals[i], glm::dvec3(b.normals[i])) < 1e-5);
    }
}

TEST_CASE("Lab 10: blendMd2Frames mixes positions and gives normals of unit length along the mix", "[lab10][crowds]") {
    Md2Frame a, b;
    a.positions = {{0.0f, 0.0f, 0.0f}};
    b.positions = {{2.0f, -4.0f, 8.0f}};
    a.normals = {{1.0f, 0.0f, 0.0f}};
    b.normals = {{0.0f, 1.0f, 0.0f}};
    std::vector<glm::vec3> positions, normals;
    blendMd2Frames(a, b, 0.5f, positions, normals);
    REQUIRE(normals.size() == 1);
    CHECK(distance(positions[0], {1.0, -2.0, 4.0}) < 1e-6);
    CHECK(distance(normals[0], {std::sqrt(0.5), std::sqrt(0.5), 0.0}) < 1e-6);

    test::Random random(9191);
    int compared = 0;
    for (int trial = 0; trial < 20; ++trial) {
        const Md2Frame first = randomFrame(random, 100), second = randomFrame(random, 100);
        const float t = random.uniform(0.0f, 1.0f);
        blendMd2Frames(first, second, t, positions, normals);
        for (std::size_t i = 0; i < 100; ++i) {
            const glm::dvec3 p = glm::dvec3(first.positions[i]) * (1.0 - t) + glm::dvec3(second.positions[i]) * double(t);
            const glm::dvec3 n = glm::dvec3(first.normals[i]) * (1.0 - t) + glm::dvec3(second.normals[i]) * double(t);
            INFO("trial " << trial << ", vertex " << i << ", t " << t);
            REQUIRE(distance(positions[i], p) < 2e-5);
            if (glm::length(n) < 0.1) continue;   // nearly opposite normals: any direction will do
            REQUIRE(std::abs(glm::length(glm::dvec3(normals[i])) - 1.0) < 1e-5);
            REQUIRE(distance(normals[i], glm::normalize(n)) < 1e-4);
            ++compared;
        }
    }
    CHECK(compared > 1800);
}

TEST_CASE("Lab 10: blendMd2Frames resizes its outputs to the frame's vertex count", "[lab10][crowds]") {
    test::Random random(9292);
    const Md2Frame a = randomFrame(random, 37), b = randomFrame(random, 37);
    std::vector<glm::vec3> positions(500, glm::vec3(9.0f)), normals(3, glm::vec3(9.0f));
    blendMd2Frames(a, b, 0.25f, positions, normals);
    CHECK(positions.size() == 37);
    CHECK(normals.size() == 37);
    positions.clear();
    normals.assign(80, glm::vec3(0.0f));
    blendMd2Frames(a, b, 0.75f, positions, normals);
    CHECK(positions.size() == 37);
    CHECK(normals.size() == 37);
    const Md2Frame none;
    blendMd2Frames(none, none, 0.5f, positions, normals);
    CHECK(positions.empty());
    CHECK(normals.empty());
}
