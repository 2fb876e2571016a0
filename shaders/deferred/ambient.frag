#version 330 core
#include "common/frame.glsl"
#include "08_deferred/g_buffer.glsl"
#include "deferred/gbuffer_read.glsl"
#include "deferred/lighting.glsl"
// The first lighting pass of labs 08-09, over the whole picture: ambient light
// (times the ambient occlusion of lab 09 when there is one) and the moon, or
// the sky where nothing was drawn. The point lights are added after it.

uniform sampler2D uAmbientOcclusion;
uniform bool uHasAmbientOcclusion;
uniform float uShininess;
uniform vec3 uMoonDirectionView;
uniform vec3 uSky;

out vec4 fragColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface surface = readSurface(pixel);
    if (surface.sky) {
        fragColor = vec4(uSky, 1.0);
        return;
    }
    float ao = uHasAmbientOcclusion ? texelFetch(uAmbientOcclusion, pixel, 0).r : 1.0;
    vec3 moon = uDirectionalLightCount > 0 ? uDirectionalLights[0].color : vec3(0.0);
    fragColor = vec4(ambientAndDirectional(surface.position, surface.normal, surface.albedo, surface.specular, uShininess,
                                           uAmbient, uMoonDirectionView, moon, ao), 1.0);
}
