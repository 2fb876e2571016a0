// The orbit camera: its state, the student's functions that change it
// (StudentCode::cameras), and the mouse mapping that calls them.

#include <stoa/app/Input.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/StudentCode.hpp>

namespace stoa {

namespace {
constexpr float kDegreesPerPixel = 0.3f;
}

OrbitCamera::OrbitCamera(glm::vec3 target, float distance, float yawDegrees, float pitchDegrees)
    : m_orbit{target, distance, yawDegrees, pitchDegrees} {
    STOA_ASSERT(distance > 0.0f, "OrbitCamera::OrbitCamera(): the distance to the target must be positive");
}

glm::vec3 OrbitCamera::eyePosition() const { return studentCode().cameras.eyePosition(m_orbit); }

void OrbitCamera::tumble(float deltaYawDegrees, float deltaPitchDegrees) {
    studentCode().cameras.tumble(m_orbit, deltaYawDegrees, deltaPitchDegrees);
}

void OrbitCamera::track(float right, float up) { studentCode().cameras.track(m_orbit, right, up); }

void OrbitCamera::dolly(float amount) { studentCode().cameras.dolly(m_orbit, amount); }

void OrbitCamera::mouseDragged(const InputState& input, glm::vec2 delta) {
    const bool left = input.button(MouseButton::Left);
    const bool middle = input.button(MouseButton::Middle);
    const bool right = input.button(MouseButton::Right);
    // Alt is Maya's modifier; the same gestures work without it.
    if (middle || (left && input.shift)) {
        // Track: one pixel moves the target by the size of a pixel at the target's depth.
        const float unitsPerPixel = m_orbit.distance * 0.0015f;
        track(-delta.x * unitsPerPixel, delta.y * unitsPerPixel);
    } else if (right || (left && input.control)) {
        dolly((delta.x - delta.y) * 0.01f);
    } else if (left) {
        tumble(-delta.x * kDegreesPerPixel, delta.y * kDegreesPerPixel);
    }
}

void OrbitCamera::mouseWheel(int notches) { dolly(0.1f * static_cast<float>(notches)); }

} // namespace stoa
