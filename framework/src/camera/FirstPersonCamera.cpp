// The first-person camera: its state, the student's functions that change it
// (StudentCode::cameras), and the mouse and key mapping that calls them.

#include <stoa/app/Input.hpp>
#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/core/StudentCode.hpp>

namespace stoa {

namespace {
constexpr float kDegreesPerPixel = 0.3f;
}

FirstPersonCamera::FirstPersonCamera(glm::vec3 position, float yawDegrees, float pitchDegrees)
    : m_view{position, yawDegrees, pitchDegrees} {}

glm::vec3 FirstPersonCamera::forward() const { return studentCode().cameras.forward(m_view); }

void FirstPersonCamera::look(float deltaYawDegrees, float deltaPitchDegrees) {
    studentCode().cameras.look(m_view, deltaYawDegrees, deltaPitchDegrees);
}

void FirstPersonCamera::move(const glm::vec3& amount) { studentCode().cameras.move(m_view, amount); }

void FirstPersonCamera::mouseDragged(const InputState& input, glm::vec2 delta) {
    if (input.button(MouseButton::Right)) look(-delta.x * kDegreesPerPixel, -delta.y * kDegreesPerPixel);
}

void FirstPersonCamera::update(const InputState& input, float seconds) {
    glm::vec3 direction(0.0f);
    if (input.key('w')) direction.z += 1.0f;
    if (input.key('s')) direction.z -= 1.0f;
    if (input.key('d')) direction.x += 1.0f;
    if (input.key('a')) direction.x -= 1.0f;
    if (input.key(' ')) direction.y += 1.0f;
    if (input.control || input.key('c')) direction.y -= 1.0f;
    if (direction == glm::vec3(0.0f)) return;
    const float distance = speed * seconds * (input.shift ? 4.0f : 1.0f);
    move(direction * distance);
}

} // namespace stoa
