// Lab 02: the vertex transform. Read docs/labs/02_shading.md, "The vertex stage".
// shaders/forward/blinn_phong.vert calls these for every vertex.

// Object-space position -> clip space.
vec4 clipPosition(mat4 model, mat4 view, mat4 projection, vec3 positionObject) {
    // TODO(lab02): apply the model, view and projection matrices, in the right order.
    return STOA_NOT_IMPLEMENTED(vec4(0.0));
}

// Object-space normal -> world space (normalMatrix is the inverse transpose of the model's 3x3).
vec3 worldNormal(mat3 normalMatrix, vec3 normalObject) {
    // TODO(lab02): transform the normal.
    return STOA_NOT_IMPLEMENTED(vec3(0.0, 1.0, 0.0));
}
