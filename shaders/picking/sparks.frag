#version 330 core
// Lab 07's sparks: a round glow, white-hot in the middle, orange at the rim,
// fading with age; added to what is behind (additive blending).

in vec2 vCorner;
in float vAge;

out vec4 fragColor;

void main() {
    float r2 = dot(vCorner, vCorner);
    if (r2 > 1.0) discard;
    float glow = (1.0 - r2) * (1.0 - vAge);
    fragColor = vec4(vec3(1.0, 0.55, 0.15) * glow + vec3(0.6, 0.5, 0.4) * glow * glow, 1.0);
}
