#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
#include "07_picking/student/particles.glsl"
// Lab 07's sparks: one square per spark (four vertices as a triangle strip,
// drawn instanced), turned to the camera by the student's billboardCorner().

layout(location = 0) in vec4 aSpark;   // per spark: xyz its centre, w its age / lifetime

uniform float uHalfSize;   // metres

out vec2 vCorner;
out float vAge;

void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    vCorner = corner;
    vAge = aSpark.w;
    vec3 positionWorld = billboardCorner(aSpark.xyz, corner, uHalfSize, uView);
    gl_Position = uProjection * uView * vec4(positionWorld, 1.0);
}
