#pragma once
// A camera that walks and flies: hold the right mouse button and drag to look
// around; W/A/S/D move forward, left, back and right; Space rises and Ctrl (or C)
// sinks; Shift moves four times faster.
//
// State: position, yaw and pitch (lab 01 writes forward(), look() and move()).

#include <stoa/camera/Camera.hpp>

namespace stoa {

class FirstPersonCamera : public Camera {
public:
    FirstPersonCamera() = default;
    /// yaw: degrees about +Y, 0 looks down -Z; pitch: degrees up, in [-89, 89].
    FirstPersonCamera(glm::vec3 position, float yawDegrees, float pitchDegrees);

    glm::vec3 eyePosition() const override { return m_position; }
    glm::vec3 lookTarget() const override { return m_position + forward(); }

    /// Unit view direction from yaw and pitch (lab 01).
    glm::vec3 forward() const;
    /// Turns the view: yaw += deltaYaw, pitch += deltaPitch, pitch kept in [-89, 89] (lab 01).
    void look(float deltaYawDegrees, float deltaPitchDegrees);
    /// Moves the eye by `amount` world units in the camera's frame: x along the
    /// horizontal right vector, y along world up, z along the horizontal forward
    /// direction (the walk ignores pitch, as in most games) (lab 01).
    void move(const glm::vec3& amount);

    glm::vec3 position() const { return m_position; }
    float yawDegrees() const { return m_yawDegrees; }
    float pitchDegrees() const { return m_pitchDegrees; }

    /// World units per second at normal speed.
    float speed = 3.0f;

    void mouseDragged(const InputState& input, glm::vec2 deltaPixels) override;
    void update(const InputState& input, float seconds) override;

private:
    glm::vec3 m_position{0.0f, 1.0f, 5.0f};
    float m_yawDegrees = 0.0f;
    float m_pitchDegrees = 0.0f;
};

} // namespace stoa
