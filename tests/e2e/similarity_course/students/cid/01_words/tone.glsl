// Lab 01: two tone functions.

// The Reinhard tone map of an HDR colour after exposure.
vec3 toneMap(vec3 color, float exposure) {
    color *= exposure;
    color /= color + 1.0;
    return exp(log(max(color, vec3(1e-6))) / 2.2);
}

// A toon ramp: n dot l quantized into `levels` bands, the first band at least 0.1.
float bands(float nDotL, int levels) {
    float n = float(levels > 0 ? levels : 1);
    return clamp(floor(nDotL * n) / n, 0.1, 1.0);
}
