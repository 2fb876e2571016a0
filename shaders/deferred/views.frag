#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
#include "deferred/gbuffer_read.glsl"
// The pictures of labs 08-09 besides the lit one, and the lit one itself:
//   uMode 0  the lit picture (uImage, the light accumulation), clamped to [0, 1]
//         1  albedo              2  normals (view space, n * 0.5 + 0.5)
//         3  positions: the world position rebuilt from depth, fract() of each
//            coordinate (a 1 m grid in colour, offset by half a metre)
//         4  specular strength   5  a heat map of uImage.r / uHeatScale

uniform sampler2D uImage;
uniform int uMode;
uniform float uHeatScale;
uniform mat4 uInverseView;

out vec4 fragColor;

// Black, blue, cyan, green, yellow, red, white as t goes from 0 to 1.
vec3 heat(float t) {
    const vec3 stops[7] = vec3[7](vec3(0.0), vec3(0.0, 0.1, 0.7), vec3(0.0, 0.7, 0.9), vec3(0.1, 0.8, 0.2),
                                  vec3(0.95, 0.9, 0.1), vec3(0.95, 0.15, 0.05), vec3(1.0));
    float x = clamp(t, 0.0, 1.0) * 6.0;
    int i = min(int(x), 5);
    return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (uMode == 0) {
        fragColor = vec4(clamp(texelFetch(uImage, pixel, 0).rgb, 0.0, 1.0), 1.0);
        return;
    }
    if (uMode == 5) {
        fragColor = vec4(heat(texelFetch(uImage, pixel, 0).r / uHeatScale), 1.0);
        return;
    }
    Surface surface = readSurface(pixel);
    if (surface.sky) {
        fragColor = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec3 color = surface.albedo;
    if (uMode == 2) color = surface.normal * 0.5 + 0.5;
    if (uMode == 3) color = fract((uInverseView * vec4(surface.position, 1.0)).xyz + 0.5);   // +0.5: the floor (y = 0) away from the jump
    if (uMode == 4) color = vec3(surface.specular);
    fragColor = vec4(color, 1.0);
}
