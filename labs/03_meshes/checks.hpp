#pragma once
// Lab 03's property checks (the cases with a `check` key in cases.ini), for what
// the pictures cannot show. See docs/labs/03_meshes.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab03 {

/// degenerate_triangles: facetNormals() and smoothNormals() on a mesh with a
/// triangle of zero area, a triangle with a zero-length edge and a vertex no
/// triangle uses: every normal is a finite unit vector, a degenerate triangle
/// adds nothing, and what gets nothing is +Y (docs: "Facet normals", "Smooth normals").
stoa::CheckResult checkDegenerateTriangles();
stoa::CheckResult checkAngleWeights();

} // namespace lab03
