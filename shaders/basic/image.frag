#version 330 core
// Shows an RGBA picture as it is (the lab window's "yours / reference / difference" views).
in vec2 vUv;
out vec4 fragColor;

uniform sampler2D uImage;

void main() {
    fragColor = vec4(texture(uImage, vUv).rgb, 1.0);
}
