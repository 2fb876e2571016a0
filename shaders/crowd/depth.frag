#version 330 core
// The sun's shadow map: depth only.
void main() {}
