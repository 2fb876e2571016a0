#version 330 core
// Lab 03's fragment stage: the material from the texture maps (the student's
// textures.glsl), lit by ambient plus every light with the student's lab-02
// lighting.glsl. The maps and their flags are MeshObject's uniforms
// (framework/include/stoa/scene/MeshObject.hpp).
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
#include "02_shading/student/lighting.glsl"
#include "03_meshes/student/textures.glsl"

in vec3 vPositionWorld;
in vec3 vNormalWorld;
in vec2 vUv;
uniform Material uMaterial;

uniform sampler2D uDiffuseMap;   // texture unit 0
uniform bool uHasDiffuseMap;
uniform sampler2D uSpecularMap;  // texture unit 1
uniform bool uHasSpecularMap;

out vec4 fragColor;

void main() {
    vec3 N = surfaceNormal(vNormalWorld);
    vec3 V = normalize(uCameraPosition - vPositionWorld);
    Material material = mappedMaterial(uMaterial, vUv, uDiffuseMap, uHasDiffuseMap, uSpecularMap, uHasSpecularMap);

    vec3 color = uAmbient * material.ambient;
    for (int i = 0; i < uDirectionalLightCount; ++i)
        color += directionalLight(uDirectionalLights[i], N, V, material);
    for (int i = 0; i < uPointLightCount; ++i)
        color += pointLight(uPointLights[i], vPositionWorld, N, V, material);
    fragColor = vec4(color, 1.0);
}
