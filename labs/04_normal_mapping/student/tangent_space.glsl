// Lab 04, part 3: lighting in tangent space. Read docs/labs/04_normal_mapping.md,
// "Lighting in tangent space". shaders/normal_mapping/normal_mapped.vert calls
// tangentFrame() and toTangentSpace() for every vertex, so the eye and light
// vectors reach the fragment stage already in tangent space;
// normal_mapped.frag calls unpackNormal() for every fragment and lights with
// your lab-02 blinnPhong(), all in tangent space.

// The tangent frame in world space, as the columns (T, B, N) of a matrix: it
// takes tangent-space vectors to world space.
// model: object -> world. normalMatrix: the inverse transpose of model's 3x3.
// tangentObject: xyz the object-space tangent, w the handedness (+1 or -1).
mat3 tangentFrame(mat4 model, mat3 normalMatrix, vec3 normalObject, vec4 tangentObject) {
    // TODO(lab04): N through the normal matrix, T through the model matrix (T lies
    // in the surface, like an edge), both normalized; T made perpendicular to N
    // again (a non-uniform scale tilts it); B from N, T and the handedness.
    return STOA_NOT_IMPLEMENTED(mat3(1.0));
}

// Equation (1) of Velázquez-Armendáriz and Millán (2006): a world-space vector expressed in the tangent frame
// (its components along T, B and N). tangentToWorld comes from tangentFrame().
vec3 toTangentSpace(mat3 tangentToWorld, vec3 vectorWorld) {
    // TODO(lab04): the inverse of tangentToWorld. Its columns are orthonormal.
    return STOA_NOT_IMPLEMENTED(vectorWorld);
}

// A normal-map texel (r, g, b in [0, 1]) -> the unit tangent-space normal it
// stores (components in [-1, 1]; (0.5, 0.5, 1) is the unbent normal (0, 0, 1)).
vec3 unpackNormal(vec3 texel) {
    // TODO(lab04): undo the packing n * 0.5 + 0.5, and renormalize (8 bits and
    // filtering shorten the vector).
    return STOA_NOT_IMPLEMENTED(vec3(0.0, 0.0, 1.0));
}
