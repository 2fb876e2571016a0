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
    return uvec4(id & 0xFFu, (id >> 8u) & 0xFFu, (id >> 16u) & 0xFFu, id >> 24u);
}

// The id packObjectId() packed into `texel`.
uint unpackObjectId(uvec4 texel) {
    return texel.x | (texel.y << 8u) | (texel.z << 16u) | (texel.w << 24u);
}

// 1.0 where the pixel is not the selected object's but a pixel at most
// `radius` away on both axes (a square around it) is; 0.0 elsewhere, and
// everywhere when nothing is selected (selected == 0u). Pixels outside the
// texture count as not selected.
float outlineAt(usampler2D ids, ivec2 pixel, uint selected, int radius) {
    if (selected == 0u) return 0.0;
    ivec2 size = textureSize(ids, 0);
    if (unpackObjectId(texelFetch(ids, pixel, 0)) == selected) return 0.0;
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            ivec2 neighbour = pixel + ivec2(dx, dy);
            if (any(lessThan(neighbour, ivec2(0))) || any(greaterThanEqual(neighbour, size))) continue;
            if (unpackObjectId(texelFetch(ids, neighbour, 0)) == selected) return 1.0;
        }
    }
    return 0.0;
}
