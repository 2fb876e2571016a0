#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
#include "deferred/gbuffer_read.glsl"
#include "deferred/lighting.glsl"
// Lab 08's light-volume pass: each fragment of a light's sphere lights the
// G-buffer pixel under it with that one light; the state the spheres are drawn
// with (lightVolumeState()) decides which fragments there are. With
// uCountOnly, each fragment adds 1 instead (the overdraw heat map).

uniform vec3 uLightPosition;     // view space
uniform vec3 uLightColor;
uniform vec3 uLightAttenuation;
uniform float uLightReach;       // lightReach(): the light is 0 beyond it
uniform float uCutoff;
uniform float uShininess;
uniform bool uCountOnly;

out vec4 fragColor;

void main() {
    if (uCountOnly) {
        fragColor = vec4(1.0);
        return;
    }
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    bool sky;
    vec3 position = readPosition(pixel, sky);
    // The sphere covers pixels whose surface lies far in front of it or behind
    // it too: those are left before the rest of the G-buffer is read.
    vec3 toLight = uLightPosition - position;
    if (sky || dot(toLight, toLight) > uLightReach * uLightReach) discard;
    Surface surface = completeSurface(pixel, position, sky);
    fragColor = vec4(pointLightShade(surface.position, surface.normal, surface.albedo, surface.specular, uShininess,
                                     uLightPosition, uLightColor, uLightAttenuation, uCutoff), 1.0);
}
