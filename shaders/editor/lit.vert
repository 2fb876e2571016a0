#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
// The editor's default material (lab 11, stoa-editor): world-space position,
// normal and uv on to lit.frag. No student code here.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vPositionWorld;
out vec3 vNormalWorld;
out vec2 vUv;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vPositionWorld = world.xyz;
    vNormalWorld = uNormalMatrix * aNormal;
    vUv = aUv;
    gl_Position = uProjection * uView * world;
}
