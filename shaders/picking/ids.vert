#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
// Lab 07's ID pass: only positions; every fragment gets its object's id.

layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;

void main() {
    gl_Position = uProjection * uView * (uModel * vec4(aPosition, 1.0));
}
