// Mouse and keyboard mapping of the cameras. The camera math they call
// (tumble, track, dolly, look, move) is lab 01's.

#include <stoa/app/Input.hpp>
#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/Assert.hpp>

namespace stoa {

namespace {
constexpr float kDegreesPerPixel = 0.3f;
}

OrbitCamera::OrbitCamera(glm::vec3 target, float distance, float yawDegrees, float pitchDegrees)
    : m_target(target), m_distance(distance), m_yawDegrees(yawDegrees), m_pitchDegrees(pitchDegrees) {
    STOA_ASSERT(distance > 0.0f, "OrbitCamera::OrbitCamera(): the distance to the target must be positive");
}

void OrbitCamera::mouseDragged(const InputState& input, glm::vec2 delta) {
    const bool left = input.button(MouseButton::Left);
    const bool middle = input.button(MouseButton::Middle);
    const bool right = input.button(MouseButton::Right);
    // Alt is Maya's modifier; the same gestures work without it.
    if (middle || (left && input.shift)) {
        // Track: one pixel moves the target by the size of a pixel at the target's depth.
        const float unitsPerPixel = m_distance * 0.0015f;
        track(-delta.x * unitsPerPixel, delta.y * unitsPerPixel);
    } else if (right || (left && input.control)) {
        dolly((delta.x - delta.y) * 0.01f);
    } else if (left) {
        tumble(-delta.x * kDegreesPerPixel, delta.y * kDegreesPerPixel);
    }
}

void OrbitCamera::mouseWheel(int notches) { dolly(0.1f * static_cast<float>(notches)); }

FirstPersonCamera::FirstPersonCamera(glm::vec3 position, float yawDegrees, float pitchDegrees)
    : m_position(position), m_yawDegrees(yawDegrees), m_pitchDegrees(pitchDegrees) {}

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
