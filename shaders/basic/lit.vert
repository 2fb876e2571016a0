#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
// A plain lit surface for the labs whose subject is not shading (lab 06's field,
// lab 07's Acropolis): positions to clip space, normals and uvs on to lit.frag.
// No student code here.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vNormalWorld;
out vec2 vUv;

void main() {
    vNormalWorld = uNormalMatrix * aNormal;
    vUv = aUv;
    gl_Position = uProjection * uView * (uModel * vec4(aPosition, 1.0));
}
