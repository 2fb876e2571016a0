#version 330 core
// Samples uTexture at the fixed point uUv, everywhere.
uniform sampler2D uTexture;
uniform vec2 uUv;

out vec4 fragColor;

void main() {
    fragColor = texture(uTexture, uUv);
}
