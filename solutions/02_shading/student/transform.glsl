// Lab 02: the vertex transform. Read docs/labs/02_shading.md, "The vertex stage".
// shaders/forward/blinn_phong.vert calls these for every vertex.

// Object-space position -> clip space.
vec4 clipPosition(mat4 model, mat4 view, mat4 projection, vec3 positionObject) {
    return projection * view * model * vec4(positionObject, 1.0);
}

// Object-space normal -> world space (normalMatrix is the inverse transpose of the model's 3x3).
vec3 worldNormal(mat3 normalMatrix, vec3 normalObject) {
    return normalMatrix * normalObject;
}
