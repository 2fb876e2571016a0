#include "StudentDoubles.hpp"

#include <stoa/core/StudentCode.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace doubles {

namespace {

glm::mat4 model(const glm::vec3& position, const glm::vec3& rotationDegrees, const glm::vec3& scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, glm::radians(rotationDegrees.z), {0.0f, 0.0f, 1.0f});
    m = glm::rotate(m, glm::radians(rotationDegrees.y), {0.0f, 1.0f, 0.0f});
    m = glm::rotate(m, glm::radians(rotationDegrees.x), {1.0f, 0.0f, 0.0f});
    return glm::scale(m, scale);
}

} // namespace

void handOverTransforms(stoa::StudentCode& code) {
    code.transforms.modelMatrix = &model;
    code.transforms.lookAtMatrix = [](const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
        return glm::lookAt(eye, target, up);
    };
    code.transforms.perspectiveMatrix = [](float fovYDegrees, float aspect, float near, float far) {
        return glm::perspective(glm::radians(fovYDegrees), aspect, near, far);
    };
}

} // namespace doubles

namespace {
// Every program that links the doubles starts with them handed over; a test
// that changes an entry does so in a stoa::StudentCodeScope, which puts it back.
[[maybe_unused]] const bool handedOver = (doubles::handOverTransforms(stoa::studentCode()), true);
} // namespace
