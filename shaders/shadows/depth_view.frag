#version 330 core
// Shows a shadow map as grey levels, near dark and far bright. A perspective
// map keeps most of its depth range close to the near plane, so its window depth
// is turned back into a distance first (docs/labs/05_shadows.md, "Seeing the map").
in vec2 vUv;

uniform sampler2D uDepthMap;
uniform bool uPerspective;
uniform float uNear;   // world units, perspective maps only
uniform float uFar;

out vec4 fragColor;

void main() {
    float depth = texture(uDepthMap, vUv).r;
    float shade = depth;
    if (uPerspective) {
        float ndc = depth * 2.0 - 1.0;
        float distance = 2.0 * uNear * uFar / (uFar + uNear - ndc * (uFar - uNear));
        shade = (distance - uNear) / (uFar - uNear);
    }
    fragColor = vec4(vec3(shade), 1.0);
}
