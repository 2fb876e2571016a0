#version 330 core
// Lab 05's first pass writes depth only; the fixed pipeline stores gl_FragCoord.z.
void main() {
}
