#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
// The editor's default material: Blinn-Phong (Blinn 1977) under the sun and
// every point light, the diffuse colour from the material or its diffuse map.
// Edit it live in stoa-editor's shader panel; lab 02 derives the terms.

in vec3 vPositionWorld;
in vec3 vNormalWorld;
in vec2 vUv;
uniform Material uMaterial;
uniform sampler2D uDiffuseMap;
uniform bool uHasDiffuseMap;

out vec4 fragColor;

vec3 blinnPhong(vec3 L, vec3 lightColor, vec3 N, vec3 V, vec3 albedo) {
    float diffuse = max(dot(N, L), 0.0);
    if (diffuse <= 0.0) return vec3(0.0);
    vec3 H = normalize(L + V);
    float specular = pow(max(dot(N, H), 0.0), uMaterial.shininess);
    return lightColor * (albedo * diffuse + uMaterial.specular * specular);
}

void main() {
    vec3 N = normalize(vNormalWorld);
    vec3 V = normalize(uCameraPosition - vPositionWorld);
    vec3 albedo = uHasDiffuseMap ? texture(uDiffuseMap, vUv).rgb : uMaterial.diffuse;
    vec3 color = uAmbient * albedo;
    for (int i = 0; i < uDirectionalLightCount; ++i)
        color += blinnPhong(-normalize(uDirectionalLights[i].direction), uDirectionalLights[i].color, N, V, albedo);
    for (int i = 0; i < uPointLightCount; ++i) {
        vec3 toLight = uPointLights[i].position - vPositionWorld;
        float d = length(toLight);
        vec3 k = uPointLights[i].attenuation;
        color += blinnPhong(toLight / d, uPointLights[i].color, N, V, albedo) / (k.x + k.y * d + k.z * d * d);
    }
    fragColor = vec4(color, 1.0);
}
