#version 330 core
// The ground and the scenery of a crowd world (stoa/render/CrowdRenderer.hpp),
// one object per draw.
#include "common/frame.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uLightSpace;    // world -> the sun's shadow map, [0, 1] on every axis

out vec3 vNormalWorld;
out vec2 vUv;
out vec4 vTint;
out vec3 vShadowCoord;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vNormalWorld = uNormalMatrix * aNormal;
    vUv = aUv;
    vTint = vec4(0.0);   // no tint (md2.vert tints a selected agent)
    vShadowCoord = (uLightSpace * world).xyz;
    gl_Position = uProjection * uView * world;
}
