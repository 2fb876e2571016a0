#pragma once
// A camera that walks and flies: hold the right mouse button and drag to look
// around; W/A/S/D move forward, left, back and right; Space rises and Ctrl (or C)
// sinks; Shift moves four times faster.
//
// State: position, yaw and pitch (FirstPersonState). What looking and walking do
// to it is student code (StudentCode::cameras: forward, look, move); the
// members below call it.

#include <stoa/camera/Camera.hpp>

namespace stoa {

/// What the first-person camera keeps.
struct FirstPersonState {
    glm::vec3 position{0.0f, 1.0f, 5.0f};
    float yawDegrees = 0.0f;     // about +Y; 0 looks down -Z
    float pitchDegrees = 0.0f;   // up, in [-89, 89]
};

class FirstPersonCamera : public Camera {
public:
    FirstPersonCamera() = default;
    /// yaw: degrees about +Y, 0 looks down -Z; pitch: degrees up, in [-89, 89].
    FirstPersonCamera(glm::vec3 position, float yawDegrees, float pitchDegrees);

    glm::vec3 eyePosition() const override { return m_view.position; }
    glm::vec3 lookTarget() const override { return m_view.position + forward(); }

    /// Unit view direction from yaw and pitch.
    glm::vec3 forward() const;
    /// Turns the view: yaw += deltaYaw, pitch += deltaPitch, pitch kept in [-89, 89].
    void look(float deltaYawDegrees, float deltaPitchDegrees);
    /// Moves the eye by `amount` world units in the camera's frame: x along the
    /// horizontal right vector, y along world up, z along the horizontal forward
    /// direction (the walk ignores pitch, as in most games).
    void move(const glm::vec3& amount);

    glm::vec3 position() const { return m_view.position; }
    float yawDegrees() const { return m_view.yawDegrees; }
    float pitchDegrees() const { return m_view.pitchDegrees; }
    const FirstPersonState& state() const { return m_view; }

    /// World units per second at normal speed.
    float speed = 3.0f;

    void mouseDragged(const InputState& input, glm::vec2 deltaPixels) override;
    void update(const InputState& input, float seconds) override;

private:
    FirstPersonState m_view;
};

} // namespace stoa
