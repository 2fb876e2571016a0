#pragma once
// A camera: where the eye is, where it looks, and how the view is projected.
// Subclasses keep a few independent parameters (an orbit's yaw and pitch, a
// walker's position) and derive the rest, so nothing stored can disagree.

#include <glm/mat4x4.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace stoa {

struct InputState;

class Camera {
public:
    virtual ~Camera() = default;

    /// World-space position of the eye.
    virtual glm::vec3 eyePosition() const = 0;
    /// World-space point the camera looks at (for the view matrix).
    virtual glm::vec3 lookTarget() const = 0;
    /// World up used to orient the view (+Y).
    glm::vec3 upVector() const { return {0.0f, 1.0f, 0.0f}; }

    /// World -> view: the student's lookAtMatrix(eyePosition(), lookTarget(), upVector()).
    glm::mat4 viewMatrix() const;
    /// View -> clip for a viewport of the given aspect ratio (width / height).
    glm::mat4 projectionMatrix(float aspect) const;

    float fovYDegrees() const { return m_fovYDegrees; }
    float nearPlane() const { return m_near; }
    float farPlane() const { return m_far; }
    /// 0 < fovYDegrees < 180, 0 < near < far.
    void setProjection(float fovYDegrees, float near, float far);

    /// Mouse drag in pixels since the last event, with the buttons and modifiers held.
    virtual void mouseDragged(const InputState& input, glm::vec2 deltaPixels) = 0;
    /// Mouse wheel notches (positive: away from the user).
    virtual void mouseWheel(int notches) { (void)notches; }
    /// Called every fixed step with the keys held; `seconds` is the step length.
    virtual void update(const InputState& input, float seconds) { (void)input; (void)seconds; }

private:
    float m_fovYDegrees = 50.0f;
    float m_near = 0.1f;
    float m_far = 100.0f;
};

} // namespace stoa
