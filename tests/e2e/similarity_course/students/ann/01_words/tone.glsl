// Lab 01: two tone functions.

// The Reinhard tone map of an HDR colour after exposure.
vec3 toneMap(vec3 color, float exposure) {
    vec3 exposed = color * exposure;
    vec3 mapped = exposed / (vec3(1.0) + exposed);
    return pow(mapped, vec3(1.0 / 2.2));
}

// A toon ramp: n dot l quantized into `levels` bands, the first band at least 0.1.
float bands(float nDotL, int levels) {
    float steps = float(max(levels, 1));
    float level = floor(clamp(nDotL, 0.0, 1.0) * steps) / steps;
    return max(level, 0.1);
}
