#version 330 core
// Lab 04's fragment stage: lab 02's Blinn-Phong in tangent space, with the
// normal from the normal map (04_normal_mapping/student/tangent_space.glsl unpacks it).
// docs/labs/04_normal_mapping.md, "Lighting in tangent space".
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
#include "02_shading/student/lighting.glsl"
#include "04_normal_mapping/student/tangent_space.glsl"

#define BUMP_DIRECTIONAL_LIGHTS 2
#define BUMP_POINT_LIGHTS 2

// What uDisplay shows (the lab's 'v' key).
#define VIEW_SHADED 0
#define VIEW_NORMALS 1   // the world-space normal as a colour, n * 0.5 + 0.5

in vec2 vUv;
in mat3 vTangentToWorld;
in vec3 vToEyeTangent;
in vec3 vToDirectionalTangent[BUMP_DIRECTIONAL_LIGHTS];
in vec3 vToPointTangent[BUMP_POINT_LIGHTS];
uniform Material uMaterial;
uniform bool uHasDiffuseMap;
uniform sampler2D uDiffuseMap;
uniform bool uHasNormalMap;
uniform sampler2D uNormalMap;
uniform bool uNormalMapping;   // the 'n' key: false lights with the unbent normal
uniform int uDisplay;   // the 'v' key: VIEW_SHADED or VIEW_NORMALS

out vec4 fragColor;

// 0 when the light is behind the mesh's own surface (L.z <= 0 in tangent space):
// a bent normal may still face it, but the surface itself is in its shadow.
// A short ramp instead of a step, so the terminator does not alias.
float facesLight(vec3 L) { return smoothstep(0.0, 0.05, L.z); }

void main() {
    // (0, 0, 1) in tangent space is the mesh's own normal.
    vec3 N = vec3(0.0, 0.0, 1.0);
    if (uNormalMapping && uHasNormalMap) N = unpackNormal(texture(uNormalMap, vUv).rgb);
    if (uDisplay == VIEW_NORMALS) {
        fragColor = vec4(normalize(vTangentToWorld * N) * 0.5 + 0.5, 1.0);
        return;
    }

    Material material = uMaterial;
    if (uHasDiffuseMap) {
        vec3 albedo = texture(uDiffuseMap, vUv).rgb;
        material.ambient *= albedo;
        material.diffuse *= albedo;
    }
    vec3 V = normalize(vToEyeTangent);
    vec3 color = uAmbient * material.ambient;
    // Constant loop bounds: the input arrays are indexed by constants once unrolled.
    for (int i = 0; i < BUMP_DIRECTIONAL_LIGHTS; ++i) {
        if (i >= uDirectionalLightCount) break;
        vec3 L = normalize(vToDirectionalTangent[i]);
        color += blinnPhong(N, L, V, uDirectionalLights[i].color, material) * facesLight(L);
    }
    for (int i = 0; i < BUMP_POINT_LIGHTS; ++i) {
        if (i >= uPointLightCount) break;
        float distance = length(vToPointTangent[i]);
        vec3 L = vToPointTangent[i] / distance;
        color += blinnPhong(N, L, V, uPointLights[i].color, material) *
                 attenuation(uPointLights[i].attenuation, distance) * facesLight(L);
    }
    fragColor = vec4(color, 1.0);
}
