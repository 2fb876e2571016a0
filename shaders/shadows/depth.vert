#version 330 core
// Lab 05's first pass: object space -> the light's clip space. Only depth is
// written (the shadow map has no colour attachment).
layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;
uniform mat4 uLightSpaceMatrix;

void main() {
    gl_Position = uLightSpaceMatrix * uModel * vec4(aPosition, 1.0);
}
