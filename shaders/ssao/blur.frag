#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
#include "deferred/gbuffer_read.glsl"
#include "ssao/ssao_inputs.glsl"
#include "09_ssao/student/ssao.glsl"
// Lab 09's blur pass: the raw occlusion smoothed by the student's
// blurAmbientOcclusion(), which hides the 4 x 4 noise pattern.

uniform sampler2D uRawOcclusion;

out vec4 fragAo;

void main() {
    fragAo = vec4(blurAmbientOcclusion(uRawOcclusion, ivec2(gl_FragCoord.xy)));
}
