#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
// Lab 03's vertex stage: lab 02's transforms (the student's transform.glsl)
// and lab 03's texture coordinates (textures.glsl).
#include "02_shading/student/transform.glsl"
#include "03_meshes/student/textures.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec3 vPositionWorld;
out vec3 vNormalWorld;
out vec2 vUv;

void main() {
    vPositionWorld = (uModel * vec4(aPosition, 1.0)).xyz;
    vNormalWorld = worldNormal(uNormalMatrix, aNormal);
    vUv = vertexUv(aUv);
    gl_Position = clipPosition(uModel, uView, uProjection, aPosition);
}
