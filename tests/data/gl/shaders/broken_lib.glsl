// Included by broken_include.frag: an error on line 4.

float brokenScale() {
    return 1.0 + missingScale;
}
