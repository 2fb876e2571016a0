#version 330 core
// A rectangle covering the viewport, from gl_VertexID alone (stoa::TextureOverlay
// draws 4 vertices as a triangle strip): the lab window's picture views.
out vec2 vUv;

void main() {
    vUv = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(vUv * 2.0 - 1.0, 0.0, 1.0);
}
