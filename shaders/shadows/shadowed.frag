#version 330 core
// Lab 05's second pass: the one shadow-casting light (the sun or a point light),
// lit by the student's lab-02 lighting.glsl, dimmed where the student's
// shadows.glsl finds the point hidden from the light (docs/labs/05_shadows.md).
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
#include "02_shading/student/lighting.glsl"
#include "05_shadows/student/shadows.glsl"

in vec3 vPositionWorld;
in vec3 vNormalWorld;
in vec2 vUv;
uniform Material uMaterial;

uniform int uLightKind;            // 0: uDirectionalLights[0]; 1: uPointLights[0]
uniform bool uShadowsEnabled;
uniform sampler2D uShadowMap;      // window depth in [0, 1], nearest, clamped to the edge
uniform mat4 uLightSpaceMatrix;    // world -> the light's clip space
uniform vec3 uShadowBias;          // (slope factor, minimum, maximum), in shadow-map depth units
uniform int uPcfMode;              // 0 single tap, 1 2x2, 2 3x3

out vec4 fragColor;

void main() {
    vec3 N = normalize(vNormalWorld);
    vec3 V = normalize(uCameraPosition - vPositionWorld);

    vec3 L;
    vec3 lightOut;
    if (uLightKind == 0) {
        L = normalize(-uDirectionalLights[0].direction);
        lightOut = directionalLight(uDirectionalLights[0], N, V, uMaterial);
    } else {
        L = normalize(uPointLights[0].position - vPositionWorld);
        lightOut = pointLight(uPointLights[0], vPositionWorld, N, V, uMaterial);
    }

    float s = 1.0;
    if (uShadowsEnabled) {
        vec3 coordinates = shadowMapCoordinates(uLightSpaceMatrix, vPositionWorld);
        float bias = slopeScaledBias(dot(N, L), uShadowBias);
        s = shadowFactor(uShadowMap, coordinates, bias, uPcfMode);
    }
    vec3 ambient = uAmbient * uMaterial.ambient;
    fragColor = vec4(umbraShade(ambient, lightOut, s), 1.0);
}
