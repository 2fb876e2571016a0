// Lab 01: two tone functions.

// The Reinhard tone map of an HDR colour after exposure.
vec3 toneMap(vec3 color, float exposure) {
    vec3 c = exposure * color;
    c = vec3(c.r / (1.0 + c.r), c.g / (1.0 + c.g), c.b / (1.0 + c.b));
    const float inverseGamma = 1.0 / 2.2;
    return vec3(pow(c.r, inverseGamma), pow(c.g, inverseGamma), pow(c.b, inverseGamma));
}

// A toon ramp: n dot l quantized into `levels` bands, the first band at least 0.1.
float bands(float nDotL, int levels) {
    if (levels < 1) levels = 1;
    float band = float(int(nDotL * float(levels)));
    float value = band / float(levels);
    if (value < 0.1) value = 0.1;
    if (value > 1.0) value = 1.0;
    return value;
}
