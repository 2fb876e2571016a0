#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
// Lab 01's shader: positions through the student's matrices, normals to world
// space, shaded by a light at the eye so every shape reads clearly.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vPositionWorld;
out vec3 vNormalWorld;

void main() {
    vec4 positionWorld = uModel * vec4(aPosition, 1.0);
    vPositionWorld = positionWorld.xyz;
    vNormalWorld = uNormalMatrix * aNormal;
    gl_Position = uProjection * uView * positionWorld;
}
