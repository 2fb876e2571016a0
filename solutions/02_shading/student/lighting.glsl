// Lab 02: Blinn-Phong lighting. Read docs/labs/02_shading.md.
// shaders/forward/blinn_phong.frag adds the ambient term and calls
// directionalLight() and pointLight() once per light. All vectors are in world
// space; N, L and V arrive normalized where the comments say so.
#include "common/lights.glsl"

// Equations (2) and (3): diffuse plus specular for one light.
// N: unit surface normal; L: unit vector towards the light; V: unit vector towards the eye.
vec3 blinnPhong(vec3 N, vec3 L, vec3 V, vec3 lightColor, Material material) {
    vec3 H = normalize(L + V);
    float diffuse = max(0.0, dot(N, L));
    float specular = pow(max(0.0, dot(N, H)), material.shininess);
    return lightColor * (material.diffuse * diffuse + material.specular * specular);
}

// How much of a point light's colour arrives at `distance`: 1 / (k_c + k_l d + k_q d^2).
float attenuation(vec3 coefficients, float distance) {
    return 1.0 / (coefficients.x + coefficients.y * distance + coefficients.z * distance * distance);
}

// One directional light at a surface point.
vec3 directionalLight(DirectionalLight light, vec3 N, vec3 V, Material material) {
    vec3 L = normalize(-light.direction);
    return blinnPhong(N, L, V, light.color, material);
}

// One point light at the surface point positionWorld.
vec3 pointLight(PointLight light, vec3 positionWorld, vec3 N, vec3 V, Material material) {
    vec3 toLight = light.position - positionWorld;
    float distance = length(toLight);
    vec3 L = toLight / distance;
    return blinnPhong(N, L, V, light.color, material) * attenuation(light.attenuation, distance);
}
