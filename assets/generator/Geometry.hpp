#pragma once
// The meshes of the Acropolis scene, built in code. Units are metres, +Y is up,
// every mesh stands on y = 0 (the floor is y = 0) and faces +Z where it has a
// front. Triangles are counter-clockwise seen from outside; uvs have v up.
// Each piece that should look smooth shares its vertices (its normals are the
// area-weighted average of its faces); hard edges duplicate vertices.

#include <stoa/geometry/Mesh.hpp>

namespace stoa::assets {

/// A square of stone tiles, `size` metres a side, centred on the origin,
/// cut into `cells` x `cells` quads. The texture repeats every 2 m.
Mesh floorMesh(float size = 30.0f, int cells = 4);

/// A Doric-like column 5.05 m tall: a square plinth, a rounded base ring, a
/// tapering shaft with 20 concave flutes (4 segments each, 16 rings, all
/// vertices shared so the flutes shade smoothly), an echinus and a square abacus.
Mesh columnMesh();

/// A wall slab 8 m long (X), 3 m high, 0.6 m thick; its stone texture and
/// height map repeat every 2 m on every face.
Mesh wallMesh();

/// A temple-like block: three steps (the top one is the stylobate), a cella,
/// an entablature and a gabled roof whose pediments face +Z and -Z.
/// 12 m wide (X), 9 m deep (Z), 7.3 m high.
Mesh templeMesh();

/// A statue stand-in 1.97 m tall: a draped figure of revolution with shoulders,
/// arms, neck and head, displaced by smooth noise. `slices` around the Y axis,
/// `rings` up it; closed at the bottom (a centre vertex) and the top (a pole):
/// exactly 2 * slices * rings triangles. No uvs; its normals are left to the reader.
Mesh statueMesh(int slices = 200, int rings = 100);

} // namespace stoa::assets
