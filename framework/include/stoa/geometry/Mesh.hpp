#pragma once
// A triangle mesh on the CPU: what the loaders and the procedural shapes
// produce and what the GL side uploads into a vertex array. No OpenGL here.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace stoa {

/// One corner of a triangle, in object space.
struct Vertex {
    glm::vec3 position{0.0f};  // object space
    glm::vec3 normal{0.0f};    // object space, unit length once the mesh is complete
    glm::vec2 uv{0.0f};        // texture coordinates, v up (OpenGL convention: v = 0 is the image's bottom row)
    /// Object space. xyz: unit tangent, the direction in which u grows along
    /// the surface, perpendicular to `normal`; w: handedness, +1 or -1, so that
    /// the bitangent (the direction in which v grows) is w * cross(normal, xyz).
    /// All zero until something computes tangents (lab 04).
    glm::vec4 tangent{0.0f};
};
static_assert(sizeof(Vertex) == 12 * sizeof(float), "Vertex is uploaded to the GPU as 12 tightly packed floats");

/// An indexed triangle list: every three entries of `indices` name the
/// vertices of one triangle, counter-clockwise when seen from its front.
/// The fields are public because a mesh is plain data; call validate() on
/// one that comes from outside the program.
class Mesh {
public:
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // 3 per triangle, each < vertices.size()

    std::size_t triangleCount() const { return indices.size() / 3; }

    /// Axis-aligned bounds of all vertex positions as (min, max), in object space.
    /// Asserts when the mesh has no vertices.
    std::pair<glm::vec3, glm::vec3> bounds() const;

    /// Checks the invariants above and that every position, normal, uv and tangent is
    /// finite. Throws InputError(source, 0, ...) naming the first problem;
    /// `source` names where the mesh came from (usually a file path).
    void validate(const std::string& source) const;
};

/// Framework utility: replaces every vertex normal by the normalized sum of the
/// un-normalized face normals (p1 - p0) x (p2 - p0) of the triangles that use
/// that vertex, so that larger triangles weigh more ("area-weighted" smooth
/// normals). Vertices only share a normal when they share an index: a seam
/// that duplicates vertices (for different uvs) stays visible. A vertex that
/// no triangle of non-zero area uses gets the normal +Y. Triangles too large
/// or too small for a float cross product are summed in double, so a huge
/// triangle still gets its true normal.
void computeSmoothNormals(Mesh& mesh);

} // namespace stoa
