#pragma once
// A camera that circles a target point, with Maya's mouse controls:
//   Alt+left drag: tumble (orbit)    Alt+middle drag: track (pan)    Alt+right drag: dolly
// The same without Alt, and, for a touchpad without a middle button, Shift+left
// tracks and Ctrl+left dollies. The wheel dollies too.
//
// State: target, distance, yaw and pitch (OrbitState). The eye position and the
// view follow from them. What the controls do to the state is student code
// (StudentCode::cameras: eyePosition, tumble, track, dolly); the members below
// call it.

#include <stoa/camera/Camera.hpp>

namespace stoa {

/// What the orbit camera keeps; everything else follows from it.
struct OrbitState {
    glm::vec3 target{0.0f};
    float distance = 5.0f;       // from the target to the eye, > 0
    float yawDegrees = 0.0f;     // about +Y; 0 puts the eye on +Z of the target
    float pitchDegrees = 0.0f;   // above the target's horizontal plane, in [-89, 89]
};

class OrbitCamera : public Camera {
public:
    OrbitCamera() = default;
    /// yaw: degrees about +Y, 0 puts the eye on +Z of the target; pitch: degrees above
    /// the target's horizontal plane, in [-89, 89]; distance > 0.
    OrbitCamera(glm::vec3 target, float distance, float yawDegrees, float pitchDegrees);

    glm::vec3 eyePosition() const override;
    glm::vec3 lookTarget() const override { return m_orbit.target; }

    /// Rotates the eye about the target: yaw += deltaYaw, pitch += deltaPitch,
    /// pitch kept in [-89, 89] so the view never flips.
    void tumble(float deltaYawDegrees, float deltaPitchDegrees);
    /// Moves target and eye together in the view plane: `right` units along the
    /// camera's right vector, `up` units along its up vector.
    void track(float right, float up);
    /// Moves the eye towards the target: distance *= exp(-amount); positive
    /// amounts come closer. The distance never drops below 0.05.
    void dolly(float amount);

    glm::vec3 target() const { return m_orbit.target; }
    float distance() const { return m_orbit.distance; }
    float yawDegrees() const { return m_orbit.yawDegrees; }
    float pitchDegrees() const { return m_orbit.pitchDegrees; }
    const OrbitState& state() const { return m_orbit; }

    void mouseDragged(const InputState& input, glm::vec2 deltaPixels) override;
    void mouseWheel(int notches) override;

private:
    OrbitState m_orbit;
};

} // namespace stoa
