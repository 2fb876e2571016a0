#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
// The geometry pass of labs 08-09: positions to clip space, normals to view
// space for the G-buffer. No student code here.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vNormalView;
out vec2 vUv;

void main() {
    vNormalView = mat3(uView) * (uNormalMatrix * aNormal);
    vUv = aUv;
    gl_Position = uProjection * uView * (uModel * vec4(aPosition, 1.0));
}
