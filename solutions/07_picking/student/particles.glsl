// Lab 07, part 4: the sparks as billboards. Read docs/labs/07_picking.md,
// "Sparks as billboards". shaders/picking/sparks.vert draws each spark as a
// square of four corners (corner = (-1, -1) .. (1, 1)) around its centre:
//   positionWorld = billboardCorner(aCentre, corner, size, uView);
// blended additively (their light adds up; the order does not matter).

// The world position of corner `corner` of a square of half-side `halfSize`
// centred on `centre` that faces the camera: its sides run along the camera's
// right and up directions, which are the first two rows of the view matrix's
// rotation.
vec3 billboardCorner(vec3 centre, vec2 corner, float halfSize, mat4 view) {
    vec3 right = vec3(view[0][0], view[1][0], view[2][0]);
    vec3 up = vec3(view[0][1], view[1][1], view[2][1]);
    return centre + (right * corner.x + up * corner.y) * halfSize;
}
