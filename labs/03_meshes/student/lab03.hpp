#pragma once
// Lab 03: vertex normals for an indexed triangle mesh, written in normals.cpp.
// The app (lab.cpp) and the tests include this header; docs/labs/03_meshes.md
// explains the math.

#include <stoa/geometry/Mesh.hpp>

namespace stoa {

/// Flat shading: a copy of `mesh` in which every triangle has three vertices
/// of its own (positions, uvs and tangents copied from the corners it had),
/// all with the triangle's unit face normal normalize((p1 - p0) x (p2 - p0)),
/// which points to the side from which the corners run counter-clockwise.
/// Triangle t of the result uses vertices 3t, 3t + 1, 3t + 2, in the order of
/// the input. A triangle of zero area gets the normal +Y.
[[nodiscard]] Mesh facetNormals(const Mesh& mesh);

/// Smooth shading: replaces every vertex normal by the normalized sum of the
/// unit face normals of the triangles that use the vertex, each weighted by
/// the triangle's angle at that vertex (in radians). Unlike area weighting
/// (stoa::computeSmoothNormals), the result does not change when a triangle
/// is split into smaller ones. Degenerate triangles (zero area, or a zero
/// edge at the vertex) add nothing; a vertex that gets nothing has the normal +Y.
void smoothNormals(Mesh& mesh);

} // namespace stoa
