#version 330 core
#include "common/frame.glsl"
#include "04_normal_mapping/student/tangent_space.glsl"
#include "08_deferred/student/g_buffer.glsl"
// The course pipeline's geometry pass: albedo, specular strength and the
// normal (bent by the normal map through lab 04's unpackNormal()) into the
// G-buffer by lab 08's writeGBuffer(). uTint colours an object by its level of
// detail in the "lod" view.

in vec3 vNormalView;
in vec2 vUv;
in mat3 vTangentToView;
uniform Material uMaterial;
uniform sampler2D uDiffuseMap;
uniform bool uHasDiffuseMap;
uniform sampler2D uNormalMap;
uniform bool uHasNormalMap;
uniform vec3 uTint;
uniform float uTintAmount;

layout(location = 0) out vec4 outAlbedoSpecular;
layout(location = 1) out vec2 outNormal;

void main() {
    vec3 albedo = uMaterial.diffuse;
    if (uHasDiffuseMap) albedo *= texture(uDiffuseMap, vUv).rgb;
    albedo = mix(albedo, uTint, uTintAmount);
    float specular = dot(uMaterial.specular, vec3(1.0 / 3.0));
    vec3 N = uHasNormalMap ? vTangentToView * unpackNormal(texture(uNormalMap, vUv).rgb) : vNormalView;
    N = normalize(N);
    if (!gl_FrontFacing) N = -N;   // the inside of an open mesh, lit from the side the camera sees
    writeGBuffer(albedo, specular, N, outAlbedoSpecular, outNormal);
}
