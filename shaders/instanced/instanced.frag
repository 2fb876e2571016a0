#version 330 core
// Lambert from the first directional light plus the ambient light, in the
// instance's colour.
#include "common/frame.glsl"

in vec3 vNormalWorld;
in vec4 vColor;

out vec4 fragColor;

void main() {
    vec3 N = normalize(vNormalWorld);
    vec3 light = uAmbient;
    if (uDirectionalLightCount > 0)
        light += uDirectionalLights[0].color * max(dot(N, -normalize(uDirectionalLights[0].direction)), 0.0);
    fragColor = vec4(vColor.rgb * light, vColor.a);
}
