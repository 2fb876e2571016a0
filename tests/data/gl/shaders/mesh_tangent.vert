#version 330 core
// The GpuMesh tangent at location 3; shows tangent.xy (mapped to [0, 1]) and the
// handedness sign w (-1 -> 0, +1 -> 1) as colour.
layout(location = 0) in vec3 aPosition;
layout(location = 3) in vec4 aTangent;

out vec3 vColor;

void main() {
    vColor = vec3(aTangent.xy * 0.5 + 0.5, aTangent.w * 0.5 + 0.5);
    gl_Position = vec4(aPosition, 1.0);
}
