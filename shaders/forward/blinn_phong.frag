#version 330 core
// Lab 02's fragment stage: ambient plus every light, each lit by the student's
// lighting.glsl. docs/labs/02_shading.md explains the sum.
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
#include "02_shading/student/lighting.glsl"

in vec3 vPositionWorld;
in vec3 vNormalWorld;
in vec2 vUv;
uniform Material uMaterial;

out vec4 fragColor;

void main() {
    // Interpolation shortens normals: renormalize per fragment.
    vec3 N = normalize(vNormalWorld);
    vec3 V = normalize(uCameraPosition - vPositionWorld);

    vec3 color = uAmbient * uMaterial.ambient;
    for (int i = 0; i < uDirectionalLightCount; ++i)
        color += directionalLight(uDirectionalLights[i], N, V, uMaterial);
    for (int i = 0; i < uPointLightCount; ++i)
        color += pointLight(uPointLights[i], vPositionWorld, N, V, uMaterial);
    fragColor = vec4(color, 1.0);
}
