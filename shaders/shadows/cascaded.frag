#version 330 core
// Lab 05's second pass with cascaded shadow maps (docs/labs/05_shadows.md,
// "Cascaded shadow maps"): the sun, lit by the student's lab-02 lighting.glsl,
// tested against the cascade the student's cascades.glsl picks. Only the
// cascade cases load this program, so cascades.glsl's stubs leave the other
// cases alone.
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl
#include "02_shading/student/lighting.glsl"
#include "05_shadows/student/shadows.glsl"

#define MAX_CASCADES 4

in vec3 vPositionWorld;
in vec3 vNormalWorld;
in vec2 vUv;
uniform Material uMaterial;

uniform bool uShadowsEnabled;
uniform sampler2D uCascadeMaps[MAX_CASCADES];      // window depth, nearest, clamped to the edge
uniform mat4 uCascadeMatrices[MAX_CASCADES];       // world -> cascade i's light clip space
uniform vec3 uCascadeBiases[MAX_CASCADES];         // (slope, min, max) per cascade, its window-depth units
uniform vec4 uCascadeSplits;                       // far view depth of each slice, world units
uniform int uCascadeCount;                         // 1..MAX_CASCADES
uniform int uPcfMode;                              // 0 single tap, 1 2x2, 2 3x3
uniform bool uCascadeColors;                       // tint each cascade (window key k)

out vec4 fragColor;

// The student's shadowFactor() on one cascade's map. GLSL 3.30 indexes sampler
// arrays with constant expressions only, hence the branches.
float cascadeMapFactor(int cascade, vec3 coordinates, float bias, int pcfMode) {
    if (cascade == 0) return shadowFactor(uCascadeMaps[0], coordinates, bias, pcfMode);
    if (cascade == 1) return shadowFactor(uCascadeMaps[1], coordinates, bias, pcfMode);
    if (cascade == 2) return shadowFactor(uCascadeMaps[2], coordinates, bias, pcfMode);
    if (cascade == 3) return shadowFactor(uCascadeMaps[3], coordinates, bias, pcfMode);
    return 1.0;
}

#include "05_shadows/student/cascades.glsl"

// Red, green, blue, yellow: near to far.
vec3 cascadeTint(int cascade) {
    if (cascade == 0) return vec3(1.0, 0.55, 0.55);
    if (cascade == 1) return vec3(0.55, 1.0, 0.55);
    if (cascade == 2) return vec3(0.55, 0.7, 1.0);
    if (cascade == 3) return vec3(1.0, 1.0, 0.5);
    return vec3(1.0);
}

void main() {
    vec3 N = normalize(vNormalWorld);
    vec3 V = normalize(uCameraPosition - vPositionWorld);
    vec3 L = normalize(-uDirectionalLights[0].direction);
    vec3 lightOut = directionalLight(uDirectionalLights[0], N, V, uMaterial);

    vec3 positionView = (uView * vec4(vPositionWorld, 1.0)).xyz;
    int cascade = cascadeIndex(positionView, uCascadeSplits, uCascadeCount);
    // Past the last slice cascadeShadow() is handed MAX_CASCADES, its "no map
    // covers it", whatever the count: with fewer cascades the next matrix is unset.
    if (cascade >= uCascadeCount) cascade = MAX_CASCADES;
    float s = 1.0;
    if (uShadowsEnabled)
        s = cascadeShadow(uCascadeMatrices, uCascadeBiases, cascade, vPositionWorld, dot(N, L), uPcfMode);
    vec3 ambient = uAmbient * uMaterial.ambient;
    vec3 color = umbraShade(ambient, lightOut, s);
    if (uCascadeColors) color *= cascadeTint(cascade);
    fragColor = vec4(color, 1.0);
}
