#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block, with lights.glsl

in vec3 vPositionWorld;
in vec3 vNormalWorld;
uniform Material uMaterial;

out vec4 fragColor;

void main() {
    vec3 N = normalize(vNormalWorld);
    vec3 toEye = normalize(uCameraPosition - vPositionWorld);
    // Two-sided Lambert from the eye, plus a little ambient.
    float lambert = abs(dot(N, toEye));
    vec3 color = uMaterial.diffuse * (0.25 + 0.75 * lambert);
    fragColor = vec4(color, 1.0);
}
