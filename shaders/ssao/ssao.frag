#version 330 core
#include "common/frame.glsl"           // uProjection
#include "08_deferred/student/g_buffer.glsl"   // your lab-08 unpackNormal(), viewPositionFromDepth()
#include "deferred/gbuffer_read.glsl"
// Lab 09's occlusion pass: one value per pixel, 1 open to the sky, 0 fully
// occluded, from the student's ambientOcclusion() (09_ssao/student/ssao.glsl). The sky
// (nothing drawn) gets 1.

#include "ssao/ssao_inputs.glsl"
#include "09_ssao/student/ssao.glsl"

out vec4 fragAo;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface surface = readSurface(pixel);
    if (surface.sky) {
        fragAo = vec4(1.0);
        return;
    }
    mat3 basis = kernelBasis(surface.normal, noiseVector(uNoise, pixel));
    fragAo = vec4(clamp(ambientOcclusion(surface.position, basis), 0.0, 1.0));
}
