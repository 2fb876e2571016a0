#version 330 core
#include "06_culling/student/skybox.glsl"
// Lab 06's sky: the cube map (assets/sky/) looked up by the student's skyColor().

in vec3 vDirection;
uniform samplerCube uSky;

out vec4 fragColor;

void main() {
    fragColor = vec4(skyColor(uSky, vDirection), 1.0);
}
