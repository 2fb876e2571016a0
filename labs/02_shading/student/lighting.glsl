// Lab 02: Blinn-Phong lighting. Read docs/labs/02_shading.md.
// shaders/forward/blinn_phong.frag adds the ambient term and calls
// directionalLight() and pointLight() once per light. All vectors are in world
// space; N, L and V arrive normalized where the comments say so.
#include "common/lights.glsl"

// Equations (2) and (3): diffuse plus specular for one light.
// N: unit surface normal; L: unit vector towards the light; V: unit vector towards the eye.
vec3 blinnPhong(vec3 N, vec3 L, vec3 V, vec3 lightColor, Material material) {
    // TODO(lab02): I_out = I_light k_d max(0, N.L) + I_light k_s max(0, N.H)^n, H the half vector.
    return STOA_NOT_IMPLEMENTED(vec3(0.0));
}

// How much of a point light's colour arrives at `distance`: 1 / (k_c + k_l d + k_q d^2).
float attenuation(vec3 coefficients, float distance) {
    // TODO(lab02): coefficients = (constant, linear, quadratic).
    return STOA_NOT_IMPLEMENTED(1.0);
}

// One directional light at a surface point.
vec3 directionalLight(DirectionalLight light, vec3 N, vec3 V, Material material) {
    // TODO(lab02): the vector towards this light, then blinnPhong().
    return STOA_NOT_IMPLEMENTED(vec3(0.0));
}

// One point light at the surface point positionWorld.
vec3 pointLight(PointLight light, vec3 positionWorld, vec3 N, vec3 V, Material material) {
    // TODO(lab02): the vector towards this light, its distance, blinnPhong() and attenuation().
    return STOA_NOT_IMPLEMENTED(vec3(0.0));
}
