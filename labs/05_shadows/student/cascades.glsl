// Lab 05, going further: picking and reading the cascade. Read
// docs/labs/05_shadows.md, "Cascaded shadow maps". shaders/shadows/cascaded.frag
// calls, for every fragment:
//   cascade = cascadeIndex(positionView, splits, count);
//   s = cascadeShadow(matrices, biases, cascade, positionWorld, N.L, pcfMode).
// It declares, before including this file, MAX_CASCADES (4) and
//   float cascadeMapFactor(int cascade, vec3 coordinates, float bias, int pcfMode):
// your shadowFactor() on cascade `cascade`'s map (GLSL 3.30 can index an array of
// samplers with constants only, so that choice is a chain of ifs made for you).

// The cascade whose slice holds a point at `positionView` (camera view space:
// the camera looks down -Z). splitFar[i] is the far view depth of slice i
// (world units, in front of the camera, increasing). Returns cascadeCount when the
// point lies beyond the last slice (no shadow map covers it).
int cascadeIndex(vec3 positionView, vec4 splitFar, int cascadeCount) {
    // TODO(lab05): the first slice whose far depth lies beyond the point's
    // distance in front of the camera (mind the sign of view-space z)
    // (docs: "Picking the cascade").
    return STOA_NOT_IMPLEMENTED(0);
}

// s in [0, 1] for a point at `positionWorld` in cascade `cascade`: its map's
// coordinates through that cascade's matrix, that cascade's slope-scaled bias
// (each map's texels cover a different size, so each has its own bias), and the
// filtered depth test on that cascade's map. 1.0 beyond the last cascade (the
// shader passes cascade = MAX_CASCADES there, whatever the count).
float cascadeShadow(mat4 cascadeMatrices[MAX_CASCADES], vec3 cascadeBiases[MAX_CASCADES], int cascade,
                    vec3 positionWorld, float cosTheta, int pcfMode) {
    // TODO(lab05): your shadowMapCoordinates() and slopeScaledBias() with this
    // cascade's matrix and bias, then cascadeMapFactor() (docs: "Picking the cascade").
    return STOA_NOT_IMPLEMENTED(1.0);
}
