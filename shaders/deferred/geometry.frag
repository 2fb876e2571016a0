#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
// The geometry pass of labs 08-09: each pixel's albedo, specular strength and
// normal, written into the G-buffer by the student's writeGBuffer().

in vec3 vNormalView;
in vec2 vUv;
uniform Material uMaterial;
uniform sampler2D uDiffuseMap;
uniform bool uHasDiffuseMap;
uniform sampler2D uSpecularMap;
uniform bool uHasSpecularMap;

layout(location = 0) out vec4 outAlbedoSpecular;
layout(location = 1) out vec2 outNormal;

void main() {
    vec3 albedo = uHasDiffuseMap ? texture(uDiffuseMap, vUv).rgb : uMaterial.diffuse;
    float specular = uHasSpecularMap ? texture(uSpecularMap, vUv).r : dot(uMaterial.specular, vec3(1.0 / 3.0));
    vec3 N = normalize(vNormalView);
    if (!gl_FrontFacing) N = -N;   // the inside of an open mesh, lit from the side the camera sees
    writeGBuffer(albedo, specular, N, outAlbedoSpecular, outNormal);
}
