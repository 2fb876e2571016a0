// Lab 03: facet and smooth vertex normals. Read docs/labs/03_meshes.md first.
// The declarations, with what each function must return, are in lab03.hpp
// (next to this file), which this file and the app include. Use glm::cross, glm::dot,
// glm::normalize, glm::length and std::acos; stoa::computeSmoothNormals is the
// area-weighted version you are not to call.

#include "lab03.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace stoa {

Mesh facetNormals(const Mesh& mesh) {
    // TODO(lab03): three new vertices per triangle, each with the face normal (docs: "Facet normals").
    (void)mesh;
    throw NotImplemented("facetNormals()");
}

void smoothNormals(Mesh& mesh) {
    // TODO(lab03): sum the angle-weighted unit face normals per vertex, then normalize (docs: "Smooth normals").
    (void)mesh;
    throw NotImplemented("smoothNormals()");
}

} // namespace stoa
