// Lab 07, part 3: object ids in an integer target, and the outline of the
// picked object. Read docs/labs/07_picking.md, "The ID buffer" and "The outline".
// shaders/picking/ids.frag writes, for every fragment of object `uObjectId`,
//   fragId = packObjectId(uObjectId);            // a GL_RGBA8UI target: four bytes
// the app reads the clicked pixel back, and shaders/picking/outline.frag, a pass
// over the whole picture, draws the outline where
//   outlineAt(uIds, ivec2(gl_FragCoord.xy), uSelected, uRadius) > 0.5.

// The 32-bit id in four bytes, least significant first: x holds bits 0-7,
// y bits 8-15, z bits 16-23, w bits 24-31.
uvec4 packObjectId(uint id) {
    // TODO(lab07): shift and mask: (id >> 8u) & 0xFFu is the second byte
    // (docs: "The ID buffer").
    return STOA_NOT_IMPLEMENTED(uvec4(0u));
}

// The id packObjectId() packed into `texel`.
uint unpackObjectId(uvec4 texel) {
    // TODO(lab07): the inverse of packObjectId() (docs: "The ID buffer").
    return STOA_NOT_IMPLEMENTED(0u);
}

// 1.0 where the pixel is not the selected object's but a pixel at most
// `radius` away on both axes (a square around it) is; 0.0 elsewhere, and
// everywhere when nothing is selected (selected == 0u). Pixels outside the
// texture count as not selected.
float outlineAt(usampler2D ids, ivec2 pixel, uint selected, int radius) {
    // TODO(lab07): texelFetch(ids, pixel, 0) reads one texel; compare the
    // unpacked ids of the pixel and of its neighbours with `selected`; mind the
    // texture's edges (textureSize) (docs: "The outline").
    return STOA_NOT_IMPLEMENTED(0.0);
}
