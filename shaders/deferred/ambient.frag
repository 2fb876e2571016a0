#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
#include "deferred/gbuffer_read.glsl"
#include "deferred/lighting.glsl"
#include "deferred/ambient_light.glsl"
// The first lighting pass of the light volumes (labs 08-09), over the whole
// picture: ambient light and the moon, or the sky where nothing was drawn. The
// volumes add the point lights to it.

uniform float uShininess;

out vec4 fragColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    fragColor = vec4(ambientLight(readSurface(pixel), pixel, uShininess), 1.0);
}
