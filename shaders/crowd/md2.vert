#version 330 core
// Agents (stoa/render/CrowdRenderer.hpp): one instance per agent of a type.
// Every key frame of the type's MD2 model waits in uFrames, two texels per
// vertex per frame: (position, 1) and (normal, 0). Each instance says which
// two frames to blend and how far between them (from lab 10's md2FramesAt()):
// the pose is blended here, the way blendMd2Frames() does it on the CPU.
#include "common/frame.glsl"

layout(location = 0) in vec3 aCorner;    // x: the MD2 vertex this triangle corner uses
layout(location = 2) in vec2 aUv;
layout(location = 4) in mat4 aModel;     // locations 4-7
layout(location = 8) in vec4 aFrames;    // first frame, second frame, t, highlight (0 or 1)

uniform samplerBuffer uFrames;
uniform int uVertexCount;
uniform mat4 uLightSpace;

out vec3 vNormalWorld;
out vec2 vUv;
out vec4 vTint;
out vec3 vShadowCoord;

void main() {
    int vertex = int(aCorner.x + 0.5);
    int first = (int(aFrames.x + 0.5) * uVertexCount + vertex) * 2;
    int second = (int(aFrames.y + 0.5) * uVertexCount + vertex) * 2;
    vec3 position = mix(texelFetch(uFrames, first).xyz, texelFetch(uFrames, second).xyz, aFrames.z);
    vec3 normal = normalize(mix(texelFetch(uFrames, first + 1).xyz, texelFetch(uFrames, second + 1).xyz, aFrames.z));
    vec4 world = aModel * vec4(position, 1.0);
    vNormalWorld = mat3(aModel) * normal;
    vUv = aUv;
    vTint = aFrames.w > 0.5 ? vec4(0.2, 0.9, 1.0, 0.7) : vec4(1.0, 1.0, 1.0, 0.0);   // the selected agent in cyan
    vShadowCoord = (uLightSpace * world).xyz;
    gl_Position = uProjection * uView * world;
}
