// Lab 01: the model, view and projection matrices.
// Read docs/labs/01_transforms.md first. Build your matrices from glm's vector
// operations (glm::cross, glm::dot, glm::normalize, glm::radians, glm::tan) and
// write the entries yourself: glm::lookAt, glm::perspective, glm::translate,
// glm::rotate and glm::scale are what you are reimplementing.
// glm stores matrices column by column: m[c][r] is column c, row r.

#include "lab01.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

glm::mat4 modelMatrix(const glm::vec3& position, const glm::vec3& rotationDegrees, const glm::vec3& scale) {
    const glm::vec3 angles = glm::radians(rotationDegrees);
    const float cx = std::cos(angles.x), sx = std::sin(angles.x);
    const float cy = std::cos(angles.y), sy = std::sin(angles.y);
    const float cz = std::cos(angles.z), sz = std::sin(angles.z);

    glm::mat4 rotateX(1.0f), rotateY(1.0f), rotateZ(1.0f);
    rotateX[1][1] = cx;  rotateX[2][1] = -sx;
    rotateX[1][2] = sx;  rotateX[2][2] = cx;
    rotateY[0][0] = cy;  rotateY[2][0] = sy;
    rotateY[0][2] = -sy; rotateY[2][2] = cy;
    rotateZ[0][0] = cz;  rotateZ[1][0] = -sz;
    rotateZ[0][1] = sz;  rotateZ[1][1] = cz;

    glm::mat4 scaling(1.0f);
    scaling[0][0] = scale.x;
    scaling[1][1] = scale.y;
    scaling[2][2] = scale.z;

    glm::mat4 translation(1.0f);
    translation[3] = glm::vec4(position, 1.0f);

    return translation * rotateZ * rotateY * rotateX * scaling;
}

glm::mat4 lookAtMatrix(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up) {
    const glm::vec3 back = glm::normalize(eye - target);          // view-space +Z
    const glm::vec3 right = glm::normalize(glm::cross(up, back));  // view-space +X
    const glm::vec3 trueUp = glm::cross(back, right);             // view-space +Y

    glm::mat4 view(1.0f);
    // Rows of the rotation are the camera's axes...
    for (int column = 0; column < 3; ++column) {
        view[column][0] = right[column];
        view[column][1] = trueUp[column];
        view[column][2] = back[column];
    }
    // ...and the translation moves the eye to the origin.
    view[3][0] = -glm::dot(right, eye);
    view[3][1] = -glm::dot(trueUp, eye);
    view[3][2] = -glm::dot(back, eye);
    return view;
}

glm::mat4 perspectiveMatrix(float fovYDegrees, float aspect, float near, float far) {
    const float f = 1.0f / std::tan(glm::radians(fovYDegrees) * 0.5f);
    glm::mat4 projection(0.0f);
    projection[0][0] = f / aspect;
    projection[1][1] = f;
    projection[2][2] = (far + near) / (near - far);
    projection[2][3] = -1.0f;
    projection[3][2] = 2.0f * far * near / (near - far);
    return projection;
}

} // namespace stoa
