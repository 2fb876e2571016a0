#version 330 core
// Lab 04's vertex stage: the student's tangent frame (04_normal_mapping/
// tangent_space.glsl) takes the eye and light vectors into tangent space, so
// the fragment stage lights with the normal map's normals as they are stored.
// docs/labs/04_normal_mapping.md, "Lighting in tangent space".
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
#include "02_shading/student/transform.glsl"
#include "04_normal_mapping/student/tangent_space.glsl"

// The lights lab 04 lights with: the first two of each kind (each costs a varying).
#define BUMP_DIRECTIONAL_LIGHTS 2
#define BUMP_POINT_LIGHTS 2

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aTangent;   // xyz tangent, w handedness

uniform mat4 uModel;
uniform mat3 uNormalMatrix;

out vec2 vUv;
out mat3 vTangentToWorld;                               // for the normals view
// Not normalized: an unnormalized vector interpolates linearly across a flat
// triangle, so per-fragment lengths and directions stay right.
out vec3 vToEyeTangent;
out vec3 vToDirectionalTangent[BUMP_DIRECTIONAL_LIGHTS];
out vec3 vToPointTangent[BUMP_POINT_LIGHTS];

void main() {
    vec3 positionWorld = (uModel * vec4(aPosition, 1.0)).xyz;
    mat3 tangentToWorld = tangentFrame(uModel, uNormalMatrix, aNormal, aTangent);
    vTangentToWorld = tangentToWorld;
    vToEyeTangent = toTangentSpace(tangentToWorld, uCameraPosition - positionWorld);
    for (int i = 0; i < BUMP_DIRECTIONAL_LIGHTS; ++i)
        vToDirectionalTangent[i] = toTangentSpace(tangentToWorld, -uDirectionalLights[i].direction);
    for (int i = 0; i < BUMP_POINT_LIGHTS; ++i)
        vToPointTangent[i] = toTangentSpace(tangentToWorld, uPointLights[i].position - positionWorld);
    vUv = aUv;
    gl_Position = clipPosition(uModel, uView, uProjection, aPosition);
}
