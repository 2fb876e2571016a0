// Lab 08, part 1: what the G-buffer holds and how a lighting pass reads it
// back. Read docs/labs/08_deferred.md, "The G-buffer" and "Positions from depth".
// shaders/deferred/geometry.frag calls, for every fragment of the scene,
//   writeGBuffer(albedo, specular, normalView, outAlbedoSpecular, outNormal);
// and every lighting pass (shaders/deferred/gbuffer_read.glsl) reads a pixel back with
//   normal = unpackNormal(encoded);  position = viewPositionFromDepth(uv, depth, inverseProjection);

// +1 or -1, never 0, per component: the fold of the octahedron needs a side.
vec2 signNotZero(vec2 v) {
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

// A unit normal in two numbers, both in [0, 1] (the target is GL_RG16, which
// keeps values in [0, 1] only): the octahedral mapping of Cigolle et al. (2014).
vec2 packNormal(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z < 0.0) p = (1.0 - abs(p.yx)) * signNotZero(p);
    return p * 0.5 + 0.5;
}

// The unit normal packNormal() packed.
vec3 unpackNormal(vec2 encoded) {
    vec2 p = encoded * 2.0 - 1.0;
    vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
    return normalize(n);
}

// What the geometry pass stores for one fragment: albedo in rgb and the
// specular strength in a of the first target; the packed view-space normal in
// the second.
void writeGBuffer(vec3 albedo, float specular, vec3 normalView, out vec4 albedoSpecular, out vec2 packedNormal) {
    albedoSpecular = vec4(albedo, specular);
    packedNormal = packNormal(normalize(normalView));
}

// The view-space position of the pixel at texture coordinates `uv` (both in
// [0, 1], (0, 0) the bottom-left corner) whose depth buffer holds `depth`
// (window depth, in [0, 1]); inverseProjection takes clip space back to view space.
vec3 viewPositionFromDepth(vec2 uv, float depth, mat4 inverseProjection) {
    vec4 clip = vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0);
    vec4 view = inverseProjection * clip;
    return view.xyz / view.w;
}
