#version 330 core
// An error on line 7 of this file.
out vec4 fragColor;

void main() {
    fragColor = vec4(1.0);
    fragColor += undeclaredColor;
}
