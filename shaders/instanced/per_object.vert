#version 330 core
// One object per draw, with the per-object uniforms of ObjectUniforms: the
// same picture as instanced.vert, the other way (the instancing benchmark).
#include "common/frame.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform Material uMaterial;

out vec3 vNormalWorld;
out vec4 vColor;

void main() {
    vNormalWorld = uNormalMatrix * aNormal;
    vColor = vec4(uMaterial.diffuse, 1.0);
    gl_Position = uProjection * uView * uModel * vec4(aPosition, 1.0);
}
