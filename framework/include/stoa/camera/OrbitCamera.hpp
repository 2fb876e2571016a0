#pragma once
// A camera that circles a target point, with Maya's mouse controls:
//   Alt+left drag: tumble (orbit)    Alt+middle drag: track (pan)    Alt+right drag: dolly
// The same without Alt, and, for a touchpad without a middle button, Shift+left
// tracks and Ctrl+left dollies. The wheel dollies too.
//
// State: target, distance, yaw and pitch. The eye position and the view follow
// from them (lab 01 writes eyePosition(), tumble(), track() and dolly()).

#include <stoa/camera/Camera.hpp>

namespace stoa {

class OrbitCamera : public Camera {
public:
    OrbitCamera() = default;
    /// yaw: degrees about +Y, 0 puts the eye on +Z of the target; pitch: degrees above
    /// the target's horizontal plane, in [-89, 89]; distance > 0.
    OrbitCamera(glm::vec3 target, float distance, float yawDegrees, float pitchDegrees);

    glm::vec3 eyePosition() const override;   // lab 01
    glm::vec3 lookTarget() const override { return m_target; }

    /// Rotates the eye about the target: yaw += deltaYaw, pitch += deltaPitch,
    /// pitch kept in [-89, 89] so the view never flips (lab 01).
    void tumble(float deltaYawDegrees, float deltaPitchDegrees);
    /// Moves target and eye together in the view plane: `right` units along the
    /// camera's right vector, `up` units along its up vector (lab 01).
    void track(float right, float up);
    /// Moves the eye towards the target: distance *= exp(-amount); positive
    /// amounts come closer. The distance never drops below 0.05 (lab 01).
    void dolly(float amount);

    glm::vec3 target() const { return m_target; }
    float distance() const { return m_distance; }
    float yawDegrees() const { return m_yawDegrees; }
    float pitchDegrees() const { return m_pitchDegrees; }

    void mouseDragged(const InputState& input, glm::vec2 deltaPixels) override;
    void mouseWheel(int notches) override;

private:
    glm::vec3 m_target{0.0f};
    float m_distance = 5.0f;
    float m_yawDegrees = 0.0f;
    float m_pitchDegrees = 0.0f;
};

} // namespace stoa
