#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
#include "deferred/gbuffer_read.glsl"
#include "deferred/lighting.glsl"
#include "05_shadows/student/shadows.glsl"
// The course pipeline's sun (stoa/render/CourseRenderer.hpp), added to the
// light buffer after the point lights: Blinn-Phong from the G-buffer times s,
// the shadow factor of the cascade the student's cascades.glsl picks (lab 05).
// Not lab 05's umbraShade(), which keeps half the light in full shadow: its
// scenes have one light, this one has an ambient term and hundreds of others,
// under which a half shadow hardly shows. In the "cascades" view it writes
// each cascade's tint instead.

#define MAX_CASCADES 4

uniform mat4 uInverseView;
uniform vec3 uSunDirectionView;    // the way the light travels
uniform vec3 uSunDirectionWorld;
uniform vec3 uSunColor;
uniform float uShininess;

uniform bool uShadowsEnabled;
uniform sampler2D uCascadeMaps[MAX_CASCADES];
uniform mat4 uCascadeMatrices[MAX_CASCADES];
uniform vec3 uCascadeBiases[MAX_CASCADES];
uniform vec4 uCascadeSplits;
uniform int uCascadeCount;
uniform int uPcfMode;
uniform bool uCascadeColors;

out vec4 fragColor;

// GLSL 3.30 indexes sampler arrays with constant expressions only.
float cascadeMapFactor(int cascade, vec3 coordinates, float bias, int pcfMode) {
    if (cascade == 0) return shadowFactor(uCascadeMaps[0], coordinates, bias, pcfMode);
    if (cascade == 1) return shadowFactor(uCascadeMaps[1], coordinates, bias, pcfMode);
    if (cascade == 2) return shadowFactor(uCascadeMaps[2], coordinates, bias, pcfMode);
    if (cascade == 3) return shadowFactor(uCascadeMaps[3], coordinates, bias, pcfMode);
    return 1.0;
}

#include "05_shadows/student/cascades.glsl"

// Red, green, blue, yellow: near to far, as lab 05's cascade cases.
vec3 cascadeTint(int cascade) {
    if (cascade == 0) return vec3(1.0, 0.55, 0.55);
    if (cascade == 1) return vec3(0.55, 1.0, 0.55);
    if (cascade == 2) return vec3(0.55, 0.7, 1.0);
    if (cascade == 3) return vec3(1.0, 1.0, 0.5);
    return vec3(1.0);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    Surface surface = readSurface(pixel);
    if (surface.sky) discard;
    vec3 lightOut = ambientAndDirectional(surface.position, surface.normal, surface.albedo, surface.specular, uShininess,
                                          vec3(0.0), uSunDirectionView, uSunColor, 1.0);
    vec3 positionWorld = (uInverseView * vec4(surface.position, 1.0)).xyz;
    vec3 normalWorld = normalize(mat3(uInverseView) * surface.normal);
    int cascade = cascadeIndex(surface.position, uCascadeSplits, uCascadeCount);
    // Past the last slice cascadeShadow() is handed MAX_CASCADES, its "no map
    // covers it", whatever the count: with fewer cascades the next matrix is unset.
    if (cascade >= uCascadeCount) cascade = MAX_CASCADES;
    float s = 1.0;
    if (uShadowsEnabled)
        s = cascadeShadow(uCascadeMatrices, uCascadeBiases, cascade, positionWorld,
                          dot(normalWorld, -normalize(uSunDirectionWorld)), uPcfMode);
    if (uCascadeColors) {
        float lit = max(dot(normalWorld, -normalize(uSunDirectionWorld)), 0.0) * s;
        fragColor = vec4(cascadeTint(uShadowsEnabled ? cascade : MAX_CASCADES) * surface.albedo * (0.35 + 0.65 * lit), 1.0);
        return;
    }
    fragColor = vec4(s * lightOut, 1.0);
}
