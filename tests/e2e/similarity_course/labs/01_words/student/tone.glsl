// Lab 01: two tone functions.

// The Reinhard tone map of an HDR colour after exposure.
vec3 toneMap(vec3 color, float exposure) {
    // TODO(lab01): scale by exposure, then c / (1 + c) per channel, then gamma 2.2.
    return vec3(0.0);
}

// A toon ramp: n dot l quantized into `levels` bands, the first band at least 0.1.
float bands(float nDotL, int levels) {
    // TODO(lab01): quantize.
    return 0.0;
}
