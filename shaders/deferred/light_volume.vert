#version 330 core
#include "common/frame.glsl"
// Lab 08's light volumes: a unit sphere moved to the light and scaled to its
// reach (and a little more, so that the flat-faced mesh encloses the sphere).

layout(location = 0) in vec3 aPosition;

uniform vec3 uCenterView;
uniform float uRadius;

void main() {
    gl_Position = uProjection * vec4(uCenterView + aPosition * uRadius, 1.0);
}
