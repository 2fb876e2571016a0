#version 330 core
// The GpuMesh attribute layout; shows uv and normal as colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

out vec3 vColor;

void main() {
    vColor = vec3(aUv, aNormal.z);
    gl_Position = vec4(aPosition, 1.0);
}
