// Lab 04, part 1: a tangent frame at every vertex.
// Read docs/labs/04_normal_mapping.md, "The tangent frame", first.
// The normal map stores normals in a frame that follows the texture: x along
// the direction in which u grows (the tangent T), y along the direction in
// which v grows (the bitangent B), z along the surface normal N. The vertex
// shader needs T and the sign of B for every vertex; this file computes them.

#include "lab04.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/glm.hpp>

namespace stoa {

void computeTangents(Mesh& mesh) {
    // TODO(lab04):
    //  1. For every triangle (p0, p1, p2) with uvs (w0, w1, w2): solve the 2x2 system
    //       p1 - p0 = (u1 - u0) T + (v1 - v0) B
    //       p2 - p0 = (u2 - u0) T + (v2 - v0) B
    //     for T and B (docs: "The tangent frame"). Skip triangles whose uv
    //     determinant is (nearly) zero: their uvs give no direction.
    //  2. Add T and B to each of the triangle's three vertices.
    //  3. Per vertex: make T perpendicular to the normal (Gram-Schmidt) and
    //     unit length; w = +1 when cross(N, T) points the same way as the summed
    //     B, -1 when the other way (mirrored uvs). Store (T, w) in vertex.tangent.
    //  4. A vertex with no usable T gets any unit vector perpendicular to N, w = +1.
    (void)mesh;
    throw NotImplemented("computeTangents()");
}

} // namespace stoa
