#version 330 core
#include "stubbed_shading.glsl"

out vec4 fragColor;

void main() {
    // TODO(lab00): not a stub, STOA_NOT_IMPLEMENTED(in a comment) does not count
    fragColor = vec4(shade(vec3(0.0, 0.0, 1.0)), 1.0);
}
