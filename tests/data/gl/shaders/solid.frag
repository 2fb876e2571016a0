#version 330 core
#include "color.glsl"

out vec4 fragColor;

void main() {
    fragColor = solidColor();
}
