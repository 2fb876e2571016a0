#version 330 core
// Calls a function that is declared but defined nowhere: compiles, does not link.
vec4 neverDefined();

out vec4 fragColor;

void main() {
    fragColor = neverDefined();
}
