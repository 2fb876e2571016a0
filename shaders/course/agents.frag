#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
// A crowd's characters (crowd/md2.vert: lab 10's blended MD2 poses) into the
// course pipeline's G-buffer: the skin's colour, a little specular, the normal
// in view space, by lab 08's writeGBuffer().

in vec3 vNormalWorld;
in vec2 vUv;
in vec4 vTint;
in vec3 vShadowCoord;
uniform vec3 uDiffuse;
uniform bool uHasTexture;
uniform sampler2D uTexture;

layout(location = 0) out vec4 outAlbedoSpecular;
layout(location = 1) out vec2 outNormal;

void main() {
    vec3 albedo = uDiffuse;
    if (uHasTexture) albedo *= texture(uTexture, vUv).rgb;
    albedo = mix(albedo, vTint.rgb, vTint.a);
    vec3 N = normalize(mat3(uView) * vNormalWorld);
    if (!gl_FrontFacing) N = -N;
    writeGBuffer(albedo, 0.15, N, outAlbedoSpecular, outNormal);
}
