// Included by broken_include.frag: an error on line 5.

float brokenScale() {
    return 1.0 + missingScale;
}
