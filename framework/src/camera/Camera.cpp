#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/StudentCode.hpp>

namespace stoa {

glm::mat4 Camera::viewMatrix() const { return studentCode().transforms.lookAtMatrix(eyePosition(), lookTarget(), upVector()); }

glm::mat4 Camera::projectionMatrix(float aspect) const {
    STOA_ASSERT(aspect > 0.0f, "Camera::projectionMatrix(): aspect must be width / height of a non-empty viewport");
    return studentCode().transforms.perspectiveMatrix(m_fovYDegrees, aspect, m_near, m_far);
}

void Camera::setProjection(float fovYDegrees, float near, float far) {
    STOA_ASSERT(fovYDegrees > 0.0f && fovYDegrees < 180.0f,
                "Camera::setProjection(): the vertical field of view is in degrees, between 0 and 180");
    STOA_ASSERT(near > 0.0f && near < far, "Camera::setProjection(): planes must satisfy 0 < near < far");
    m_fovYDegrees = fovYDegrees;
    m_near = near;
    m_far = far;
}

} // namespace stoa
