#pragma once
// Procedural meshes for test scenes and labs. Every shape is centred at the
// origin, has unit-length normals pointing outward, triangles that are
// counter-clockwise seen from outside, and uvs in [0, 1] (v up). Sizes are in
// object-space units. Arguments out of range (a negative radius, fewer than
// 3 slices) are programming errors and assert.

#include <stoa/geometry/Mesh.hpp>

namespace stoa::shapes {

/// A square of side `size` in the XZ plane (y = 0), facing +Y, cut into
/// subdivisions x subdivisions quads: (subdivisions + 1)^2 vertices and
/// 2 * subdivisions^2 triangles. u grows along +X, v along -Z, so a texture
/// reads upright when the plane is seen from above with -Z at the top.
Mesh plane(float size = 1.0f, int subdivisions = 1);

/// A cube of side `size`: 24 vertices (4 per face, so each face has its own
/// flat normal and a full [0,1] uv square) and 12 triangles. Side faces have
/// v up along +Y.
Mesh cube(float size = 1.0f);

/// A UV sphere: `slices` segments around the Y axis, `stacks` from the north
/// pole (+Y) to the south pole. (slices + 1) * (stacks + 1) vertices: a grid
/// whose seam at u = 0/1 is duplicated and whose pole rows repeat the pole
/// (one copy per slice, with u in the middle of the slice; the last copy is
/// unused). 2 * slices * (stacks - 1) triangles: one per slice in the two
/// bands at the poles, two per slice elsewhere.
/// u goes around the Y axis (counter-clockwise seen from +Y, u = 0 at +Z),
/// v runs from 0 at the south pole to 1 at the north pole.
Mesh sphere(float radius = 0.5f, int slices = 32, int stacks = 16);

/// A closed cylinder around the Y axis, from y = -height/2 to y = +height/2.
/// The side has 2 * (slices + 1) vertices and 2 * slices triangles (u around,
/// v up); each cap has a centre and `slices` rim vertices of its own (flat
/// normal +Y or -Y, uvs a disc inscribed in the unit square) and `slices`
/// triangles. In all 4 * slices + 4 vertices and 4 * slices triangles.
Mesh cylinder(float radius = 0.5f, float height = 1.0f, int slices = 32);

/// A ring torus lying in the XZ plane around the Y axis: the tube's centre
/// circle has radius `majorRadius`, the tube radius `minorRadius`
/// (0 < minorRadius < majorRadius). (majorSegments + 1) * (minorSegments + 1)
/// vertices and 2 * majorSegments * minorSegments triangles; u goes around the
/// Y axis, v around the tube (v = 0 on the outer equator, v = 0.25 on top).
Mesh torus(float majorRadius = 0.4f, float minorRadius = 0.15f, int majorSegments = 48,
           int minorSegments = 24);

} // namespace stoa::shapes
