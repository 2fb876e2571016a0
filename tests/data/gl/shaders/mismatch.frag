#version 330 core
// Reads an input no vertex shader writes: compiles, does not link.
in vec3 vNeverWritten;
out vec4 fragColor;

void main() {
    fragColor = vec4(vNeverWritten, 1.0);
}
