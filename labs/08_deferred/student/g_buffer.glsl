// Lab 08, part 1: what the G-buffer holds and how a lighting pass reads it
// back. Read docs/labs/08_deferred.md, "The G-buffer" and "Positions from depth".
// shaders/deferred/geometry.frag calls, for every fragment of the scene,
//   writeGBuffer(albedo, specular, normalView, outAlbedoSpecular, outNormal);
// and every lighting pass (shaders/deferred/gbuffer_read.glsl) reads a pixel back with
//   normal = unpackNormal(encoded);  position = viewPositionFromDepth(uv, depth, inverseProjection);

// A unit normal in two numbers, both in [0, 1] (the target is GL_RG16, which
// keeps values in [0, 1] only): the octahedral mapping of Cigolle et al. (2014).
vec2 packNormal(vec3 n) {
    // TODO(lab08): project onto the octahedron |x| + |y| + |z| = 1, fold the
    // lower half (z < 0) out over the diamond's edges into its corners, then
    // map [-1, 1] to [0, 1] (docs: "Packing normals").
    return STOA_NOT_IMPLEMENTED(vec2(0.5));
}

// The unit normal packNormal() packed.
vec3 unpackNormal(vec2 encoded) {
    // TODO(lab08): the inverse of packNormal(): back to [-1, 1], unfold, normalise
    // (docs: "Packing normals").
    return STOA_NOT_IMPLEMENTED(vec3(0.0, 0.0, 1.0));
}

// What the geometry pass stores for one fragment: albedo in rgb and the
// specular strength in a of the first target; the packed view-space normal in
// the second.
void writeGBuffer(vec3 albedo, float specular, vec3 normalView, out vec4 albedoSpecular, out vec2 packedNormal) {
    // TODO(lab08): fill both outputs (docs: "The G-buffer").
    albedoSpecular = STOA_NOT_IMPLEMENTED(vec4(albedo, 0.0));
    packedNormal = vec2(0.5);
}

// The view-space position of the pixel at texture coordinates `uv` (both in
// [0, 1], (0, 0) the bottom-left corner) whose depth buffer holds `depth`
// (window depth, in [0, 1]); inverseProjection takes clip space back to view space.
vec3 viewPositionFromDepth(vec2 uv, float depth, mat4 inverseProjection) {
    // TODO(lab08): uv and depth to normalised device coordinates, through the
    // inverse projection, then divide by w (docs: "Positions from depth").
    return STOA_NOT_IMPLEMENTED(vec3(uv, -depth));
}
