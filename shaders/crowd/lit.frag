#version 330 core
// The sun (directional light 0) and the ambient light, with the sun's shadow
// map read through a 3 x 3 percentage-closer filter, on a diffuse colour
// times an optional texture. vTint.rgb is mixed in by vTint.a (a selection).
#include "common/frame.glsl"

in vec3 vNormalWorld;
in vec2 vUv;
in vec4 vTint;
in vec3 vShadowCoord;

uniform vec3 uDiffuse;
uniform bool uHasTexture;
uniform sampler2D uTexture;
uniform bool uShadows;
uniform sampler2D uShadowMap;
uniform float uShadowBias;

out vec4 fragColor;

float sunVisibility(vec3 N, vec3 L) {
    if (!uShadows) return 1.0;
    vec3 p = vShadowCoord;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return 1.0;
    float bias = uShadowBias * (1.0 + 2.0 * (1.0 - max(dot(N, L), 0.0)));
    vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0));
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x)
            lit += p.z - bias <= texture(uShadowMap, p.xy + vec2(x, y) * texel).r ? 1.0 : 0.0;
    return lit / 9.0;
}

void main() {
    vec3 N = normalize(vNormalWorld);
    if (!gl_FrontFacing) N = -N;
    vec3 albedo = uDiffuse;
    if (uHasTexture) albedo *= texture(uTexture, vUv).rgb;
    albedo = mix(albedo, vTint.rgb, vTint.a);
    vec3 light = uAmbient;
    if (uDirectionalLightCount > 0) {
        vec3 L = -normalize(uDirectionalLights[0].direction);
        light += uDirectionalLights[0].color * max(dot(N, L), 0.0) * sunVisibility(N, L);
    }
    fragColor = vec4(albedo * light, 1.0);
}
