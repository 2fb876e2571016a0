#version 330 core
#include "common/frame.glsl"
// The naive forward renderer of lab 08, for comparison: view-space position
// and normal to forward.frag, which loops over every light.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vPositionView;
out vec3 vNormalView;
out vec2 vUv;

void main() {
    vec4 positionView = uView * (uModel * vec4(aPosition, 1.0));
    vPositionView = positionView.xyz;
    vNormalView = mat3(uView) * (uNormalMatrix * aNormal);
    vUv = aUv;
    gl_Position = uProjection * positionView;
}
