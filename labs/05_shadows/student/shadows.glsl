// Lab 05: the shadow test. Read docs/labs/05_shadows.md.
// shaders/shadows/shadowed.frag calls, for every fragment:
//   coordinates = shadowMapCoordinates(...); bias = slopeScaledBias(...);
//   s = shadowFactor(...); color = umbraShade(ambient, lightOut, s).
// Depths are window depths in [0, 1], as the shadow map stores them.

// World position -> the shadow map's texture space: xy the texture coordinates
// in [0, 1] where the light sees it, z its window depth from the light.
vec3 shadowMapCoordinates(mat4 lightSpaceMatrix, vec3 positionWorld) {
    // TODO(lab05): to the light's clip space, divide by w, then from [-1, 1] to [0, 1] (docs: "Depth comparison").
    return STOA_NOT_IMPLEMENTED(vec3(0.5, 0.5, 0.0));
}

// The depth offset for a surface whose normal makes cos(theta) = N.L with the
// light. bias = (slope factor, minimum, maximum).
float slopeScaledBias(float cosTheta, vec3 bias) {
    // TODO(lab05): slope factor * tan(theta), clamped to [minimum, maximum] (docs: "Acne and the slope-scaled bias").
    return STOA_NOT_IMPLEMENTED(0.0);
}

// One unfiltered look-up: 1.0 when the point at `depth` is lit (nothing nearer
// to the light at uv), 0.0 when it is in shadow.
float shadowTap(sampler2D shadowMap, vec2 uv, float depth, float bias) {
    // TODO(lab05): compare depth - bias with the depth stored at uv.
    return STOA_NOT_IMPLEMENTED(1.0);
}

// s in [0, 1]: 0 in full shadow, 1 fully lit. pcfMode 0: one tap; 1: the four
// texels around the point (the 2x2 of Velázquez-Armendáriz and Millán 2006); 2: the 3x3 texels centred on it.
// Points outside the map (beyond its sides or its far plane) count as lit.
float shadowFactor(sampler2D shadowMap, vec3 coordinates, float bias, int pcfMode) {
    // TODO(lab05): outside the map -> 1.0; then average shadowTap() over 1, 2x2 or 3x3 texels
    // (one texel is 1.0 / textureSize(shadowMap, 0)) (docs: "Percentage-closer filtering").
    return STOA_NOT_IMPLEMENTED(1.0);
}

// Velázquez-Armendáriz and Millán (2006), eq. 4: I_frag = I_amb + 1/2 (1 + s) I_out.
vec3 umbraShade(vec3 ambient, vec3 lightOut, float s) {
    // TODO(lab05): eq. 4 (docs: "The umbra formula").
    return STOA_NOT_IMPLEMENTED(ambient + lightOut);
}
