#version 330 core
// Many copies of one mesh (stoa/render/InstancedMesh.hpp): each instance's
// model matrix and colour come as per-instance attributes.
#include "common/frame.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 4) in mat4 aModel;    // locations 4-7, one column each
layout(location = 8) in vec4 aColor;

out vec3 vNormalWorld;
out vec4 vColor;

void main() {
    // The model's 3x3 for normals: right for rotations and uniform scales.
    vNormalWorld = mat3(aModel) * aNormal;
    vColor = aColor;
    gl_Position = uProjection * uView * aModel * vec4(aPosition, 1.0);
}
