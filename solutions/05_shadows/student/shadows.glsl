// Lab 05: the shadow test. Read docs/labs/05_shadows.md.
// shaders/shadows/shadowed.frag calls, for every fragment:
//   coordinates = shadowMapCoordinates(...); bias = slopeScaledBias(...);
//   s = shadowFactor(...); color = umbraShade(ambient, lightOut, s).
// Depths are window depths in [0, 1], as the shadow map stores them.

// World position -> the shadow map's texture space: xy the texture coordinates
// in [0, 1] where the light sees it, z its window depth from the light.
vec3 shadowMapCoordinates(mat4 lightSpaceMatrix, vec3 positionWorld) {
    vec4 clip = lightSpaceMatrix * vec4(positionWorld, 1.0);
    vec3 ndc = clip.xyz / clip.w;   // [-1, 1]^3 inside the light's view volume
    return ndc * 0.5 + 0.5;
}

// The depth offset for a surface whose normal makes cos(theta) = N.L with the
// light: a texel covers more depth the more the surface slopes away from the
// light, in proportion to tan(theta). bias = (slope factor, minimum, maximum).
float slopeScaledBias(float cosTheta, vec3 bias) {
    // Not quite 0: in float, acos(0.0) rounds past pi/2, where tan() turns negative.
    float c = clamp(cosTheta, 1e-3, 1.0);
    return clamp(bias.x * tan(acos(c)), bias.y, bias.z);
}

// One unfiltered look-up: 1.0 when the point at `depth` is lit (nothing nearer
// to the light at uv), 0.0 when it is in shadow.
float shadowTap(sampler2D shadowMap, vec2 uv, float depth, float bias) {
    float nearest = texture(shadowMap, uv).r;
    return depth - bias > nearest ? 0.0 : 1.0;
}

// s in [0, 1]: 0 in full shadow, 1 fully lit. pcfMode 0: one tap; 1: the four
// texels around the point (the 2x2 of Velázquez-Armendáriz and Millán 2006); 2: the 3x3 texels centred on it.
// Points outside the map (beyond its sides or its far plane) count as lit.
float shadowFactor(sampler2D shadowMap, vec3 coordinates, float bias, int pcfMode) {
    if (coordinates.z > 1.0 || any(lessThan(coordinates.xy, vec2(0.0))) || any(greaterThan(coordinates.xy, vec2(1.0))))
        return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
    if (pcfMode == 0)
        return shadowTap(shadowMap, coordinates.xy, coordinates.z, bias);
    float sum = 0.0;
    if (pcfMode == 1) {
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) {
                vec2 offset = vec2(float(x) - 0.5, float(y) - 0.5) * texel;
                sum += shadowTap(shadowMap, coordinates.xy + offset, coordinates.z, bias);
            }
        return sum / 4.0;
    }
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec2 offset = vec2(float(x), float(y)) * texel;
            sum += shadowTap(shadowMap, coordinates.xy + offset, coordinates.z, bias);
        }
    return sum / 9.0;
}

// Velázquez-Armendáriz and Millán (2006), eq. 4: I_frag = I_amb + 1/2 (1 + s) I_out. Full shadow keeps half of
// the light (an umbra, not black); s = 1 gives the unshadowed colour.
vec3 umbraShade(vec3 ambient, vec3 lightOut, float s) {
    return ambient + 0.5 * (1.0 + s) * lightOut;
}
