// Lab 01's camera updates, the camera rig's input scripts and the fixed-step clock.

#include "catch.hpp"

#include <stoa/app/FixedStepClock.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/lab/CameraRig.hpp>

#include <glm/glm.hpp>

namespace {
bool near(glm::vec3 a, glm::vec3 b, float epsilon = 1e-4f) { return glm::length(a - b) < epsilon; }
} // namespace

TEST_CASE("OrbitCamera: yaw 0, pitch 0 puts the eye on +Z of the target") {
    stoa::OrbitCamera camera({1.0f, 2.0f, 3.0f}, 4.0f, 0.0f, 0.0f);
    CHECK(near(camera.eyePosition(), {1.0f, 2.0f, 7.0f}));
    camera.tumble(90.0f, 0.0f);
    CHECK(near(camera.eyePosition(), {5.0f, 2.0f, 3.0f}));
}

TEST_CASE("OrbitCamera: tumble keeps the pitch within [-89, 89] and the distance") {
    stoa::OrbitCamera camera(glm::vec3(0.0f), 5.0f, 10.0f, 80.0f);
    camera.tumble(0.0f, 30.0f);
    CHECK(camera.pitchDegrees() == Approx(89.0f));
    camera.tumble(0.0f, -500.0f);
    CHECK(camera.pitchDegrees() == Approx(-89.0f));
    CHECK(glm::length(camera.eyePosition()) == Approx(5.0f));
}

TEST_CASE("OrbitCamera: track moves eye and target together, sideways to the view") {
    stoa::OrbitCamera camera(glm::vec3(0.0f), 5.0f, 0.0f, 0.0f);
    const glm::vec3 eyeBefore = camera.eyePosition();
    camera.track(1.0f, 0.5f);
    CHECK(near(camera.target(), {1.0f, 0.5f, 0.0f}));
    CHECK(near(camera.eyePosition() - eyeBefore, {1.0f, 0.5f, 0.0f}));
}

TEST_CASE("OrbitCamera: dolly scales the distance by exp(-amount), never below 0.05") {
    stoa::OrbitCamera camera(glm::vec3(0.0f), 4.0f, 0.0f, 0.0f);
    camera.dolly(std::log(2.0f));
    CHECK(camera.distance() == Approx(2.0f));
    camera.dolly(100.0f);
    CHECK(camera.distance() == Approx(0.05f));
}

TEST_CASE("FirstPersonCamera: forward, look and move") {
    stoa::FirstPersonCamera camera({0.0f, 1.0f, 0.0f}, 0.0f, 0.0f);
    CHECK(near(camera.forward(), {0.0f, 0.0f, -1.0f}));
    camera.look(90.0f, 0.0f);   // turn left
    CHECK(near(camera.forward(), {-1.0f, 0.0f, 0.0f}));
    camera.move({0.0f, 0.0f, 2.0f});   // walk forward
    CHECK(near(camera.position(), {-2.0f, 1.0f, 0.0f}));
    camera.look(0.0f, 60.0f);   // looking up does not make the walk climb
    camera.move({1.0f, 0.5f, 0.0f});   // step right and rise
    CHECK(near(camera.position(), {-2.0f, 1.5f, -1.0f}));
    camera.look(0.0f, 100.0f);
    CHECK(camera.pitchDegrees() == Approx(89.0f));
}

TEST_CASE("CameraRig: input scripts drive the active camera, bad ones name the problem") {
    stoa::CameraRig rig;
    rig.orbit = stoa::OrbitCamera(glm::vec3(0.0f), 4.0f, 0.0f, 0.0f);
    rig.applyInput("tumble 90 0; dolly 0", "cases.ini", 7);
    CHECK(near(rig.orbit.eyePosition(), {4.0f, 0.0f, 0.0f}));
    CHECK_THROWS_WITH(rig.applyInput("spin 3", "cases.ini", 7),
                      Catch::Contains("cases.ini:7") && Catch::Contains("unknown command 'spin'"));
    CHECK_THROWS_WITH(rig.applyInput("tumble 1", "cases.ini", 7), Catch::Contains("takes 2 numbers"));
    CHECK_THROWS_WITH(rig.applyInput("dolly x", "cases.ini", 7), Catch::Contains("'x'"));
    CHECK_THROWS_WITH(rig.applyInput("look 1 2", "cases.ini", 7), Catch::Contains("first_person"));
}

TEST_CASE("CameraRig: toggling keeps the view") {
    stoa::CameraRig rig;
    rig.orbit = stoa::OrbitCamera({0.0f, 1.0f, 0.0f}, 5.0f, 30.0f, 20.0f);
    const glm::vec3 eye = rig.orbit.eyePosition();
    rig.toggle();
    CHECK_FALSE(rig.orbitActive());
    CHECK(near(rig.firstPerson.eyePosition(), eye));
    CHECK(near(rig.firstPerson.forward(), glm::normalize(glm::vec3(0.0f, 1.0f, 0.0f) - eye)));
    rig.toggle();
    CHECK(near(rig.orbit.eyePosition(), eye, 1e-3f));
}

TEST_CASE("FixedStepClock: whole steps from wall time, backlog dropped") {
    stoa::FixedStepClock clock(0.01, 4);
    CHECK(clock.advance(0.025) == 2);
    CHECK(clock.advance(0.006) == 1);   // 0.005 left over + 0.006
    CHECK(clock.steps() == 3);
    CHECK(clock.simulatedSeconds() == Approx(0.03));
    CHECK(clock.advance(10.0) == 4);    // a stall does not snowball
    CHECK(clock.advance(0.0) == 0);
}
