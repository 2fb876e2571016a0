#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
#include "04_normal_mapping/student/tangent_space.glsl"
// The course pipeline's geometry pass (stoa/render/CourseRenderer.hpp): positions
// to clip space; the normal, or with a normal map the student's tangent frame
// (lab 04), to view space for the G-buffer (lab 08).

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aTangent;   // xyz tangent, w handedness

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform bool uHasNormalMap;

out vec3 vNormalView;
out vec2 vUv;
out mat3 vTangentToView;   // tangent space -> view space, with a normal map

void main() {
    vNormalView = mat3(uView) * (uNormalMatrix * aNormal);
    vTangentToView = uHasNormalMap ? mat3(uView) * tangentFrame(uModel, uNormalMatrix, aNormal, aTangent) : mat3(1.0);
    vUv = aUv;
    gl_Position = uProjection * uView * (uModel * vec4(aPosition, 1.0));
}
