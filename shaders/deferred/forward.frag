#version 330 core
#include "common/frame.glsl"
#include "deferred/lighting.glsl"
// Lab 08's naive forward renderer: every fragment of every triangle loops over
// all the lights, also those that cannot reach it, and also when a nearer
// triangle will cover it later. What deferred shading avoids. No student code.

in vec3 vPositionView;
in vec3 vNormalView;
in vec2 vUv;
uniform Material uMaterial;
uniform sampler2D uDiffuseMap;
uniform bool uHasDiffuseMap;
uniform sampler2D uSpecularMap;
uniform bool uHasSpecularMap;
uniform samplerBuffer uLights;
uniform int uLightCount;
uniform float uCutoff;
uniform float uShininess;
uniform vec3 uMoonDirectionView;

out vec4 fragColor;

void main() {
    vec3 albedo = uHasDiffuseMap ? texture(uDiffuseMap, vUv).rgb : uMaterial.diffuse;
    float specular = uHasSpecularMap ? texture(uSpecularMap, vUv).r : dot(uMaterial.specular, vec3(1.0 / 3.0));
    vec3 N = normalize(vNormalView);
    if (!gl_FrontFacing) N = -N;
    vec3 moon = uDirectionalLightCount > 0 ? uDirectionalLights[0].color : vec3(0.0);
    vec3 color = ambientAndDirectional(vPositionView, N, albedo, specular, uShininess, uAmbient, uMoonDirectionView, moon, 1.0);
    for (int i = 0; i < uLightCount; ++i) {
        vec3 position, lightColor, attenuation;
        fetchLight(uLights, i, position, lightColor, attenuation);
        color += pointLightShade(vPositionView, N, albedo, specular, uShininess, position, lightColor, attenuation, uCutoff);
    }
    fragColor = vec4(color, 1.0);
}
