#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
#include "06_culling/student/skybox.glsl"
// Lab 06's sky: a cube of side 2 about the origin, placed by the student's
// skyboxClipPosition() (labs/06_culling/student/skybox.glsl). The corner is also the
// direction the fragment looks up.

layout(location = 0) in vec3 aPosition;

out vec3 vDirection;

void main() {
    gl_Position = skyboxClipPosition(aPosition, uView, uProjection);
    vDirection = aPosition;
}
