#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
// The material's diffuse colour (or its diffuse map) lit by the first
// directional light and the ambient light, two-sided. uTint, when uTintAmount > 0,
// replaces part of the colour: lab 06's overview colours each object by the
// verdict of the culling and its level of detail, lab 07 the picked object.

in vec3 vNormalWorld;
in vec2 vUv;
uniform Material uMaterial;
uniform sampler2D uDiffuseMap;
uniform bool uHasDiffuseMap;
uniform vec3 uTint;
uniform float uTintAmount;

out vec4 fragColor;

void main() {
    vec3 N = normalize(vNormalWorld);
    vec3 albedo = uHasDiffuseMap ? texture(uDiffuseMap, vUv).rgb : uMaterial.diffuse;
    albedo = mix(albedo, uTint, uTintAmount);
    vec3 color = uAmbient * albedo;
    if (uDirectionalLightCount > 0) {
        vec3 L = -normalize(uDirectionalLights[0].direction);
        color += uDirectionalLights[0].color * albedo * abs(dot(N, L));
    }
    fragColor = vec4(color, 1.0);
}
