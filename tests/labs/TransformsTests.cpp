// Lab 01's matrices against glm's, which compute the same maps another way.

#include "catch.hpp"

#include "lab01.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace {

bool near(const glm::mat4& a, const glm::mat4& b, float epsilon = 1e-5f) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (std::abs(a[c][r] - b[c][r]) > epsilon * (1.0f + std::abs(b[c][r]))) return false;
    return true;
}

} // namespace

TEST_CASE("modelMatrix is T * Rz * Ry * Rx * S") {
    const glm::vec3 position(1.5f, -2.0f, 0.25f);
    const glm::vec3 rotation(30.0f, -45.0f, 110.0f);
    const glm::vec3 scale(2.0f, 0.5f, 1.25f);
    glm::mat4 expected = glm::translate(glm::mat4(1.0f), position);
    expected = glm::rotate(expected, glm::radians(rotation.z), glm::vec3(0, 0, 1));
    expected = glm::rotate(expected, glm::radians(rotation.y), glm::vec3(0, 1, 0));
    expected = glm::rotate(expected, glm::radians(rotation.x), glm::vec3(1, 0, 0));
    expected = glm::scale(expected, scale);
    CHECK(near(stoa::modelMatrix(position, rotation, scale), expected));
}

TEST_CASE("modelMatrix with no rotation and unit scale is a translation") {
    const glm::mat4 m = stoa::modelMatrix({3.0f, 4.0f, 5.0f}, glm::vec3(0.0f), glm::vec3(1.0f));
    CHECK(near(m, glm::translate(glm::mat4(1.0f), {3.0f, 4.0f, 5.0f})));
}

TEST_CASE("lookAtMatrix matches glm::lookAt and sends the eye to the origin") {
    const glm::vec3 eye(3.0f, 2.0f, 5.0f), target(-1.0f, 0.5f, 0.0f), up(0.0f, 1.0f, 0.0f);
    const glm::mat4 view = stoa::lookAtMatrix(eye, target, up);
    CHECK(near(view, glm::lookAt(eye, target, up)));
    const glm::vec4 eyeInView = view * glm::vec4(eye, 1.0f);
    CHECK(glm::length(glm::vec3(eyeInView)) < 1e-5f);
    // The target lies straight ahead, on -Z.
    const glm::vec4 targetInView = view * glm::vec4(target, 1.0f);
    CHECK(std::abs(targetInView.x) < 1e-5f);
    CHECK(std::abs(targetInView.y) < 1e-5f);
    CHECK(targetInView.z < 0.0f);
}

TEST_CASE("perspectiveMatrix matches glm::perspective and maps near and far to -1 and 1") {
    const float fov = 50.0f, aspect = 16.0f / 9.0f, zNear = 0.1f, zFar = 100.0f;
    const glm::mat4 projection = stoa::perspectiveMatrix(fov, aspect, zNear, zFar);
    CHECK(near(projection, glm::perspective(glm::radians(fov), aspect, zNear, zFar)));
    const glm::vec4 onNear = projection * glm::vec4(0.0f, 0.0f, -zNear, 1.0f);
    const glm::vec4 onFar = projection * glm::vec4(0.0f, 0.0f, -zFar, 1.0f);
    CHECK(onNear.z / onNear.w == Approx(-1.0f).margin(1e-5));
    CHECK(onFar.z / onFar.w == Approx(1.0f).margin(1e-4));
}
