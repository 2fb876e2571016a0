#version 330 core
#include "color.glsl"
#include "broken_lib.glsl"

out vec4 fragColor;

void main() {
    fragColor = solidColor() * brokenScale();
}
