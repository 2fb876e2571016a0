#include <stoa/geometry/Mesh.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <sstream>

namespace stoa {

std::pair<glm::vec3, glm::vec3> Mesh::bounds() const {
    STOA_ASSERT(!vertices.empty(), "Mesh::bounds(): the mesh has no vertices, so it has no bounds. "
                                   "Check vertices.empty() before asking for bounds.");
    glm::vec3 lower = vertices.front().position;
    glm::vec3 upper = lower;
    for (const Vertex& vertex : vertices) {
        lower = glm::min(lower, vertex.position);
        upper = glm::max(upper, vertex.position);
    }
    return {lower, upper};
}

namespace {

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool isFinite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool isFinite(const glm::vec4& v) { return isFinite(glm::vec3(v)) && std::isfinite(v.w); }

template <typename Vector>
std::string describe(const Vector& v) {
    std::ostringstream out;
    out << '(';
    for (int i = 0; i < Vector::length(); ++i) out << (i ? ", " : "") << v[i];
    out << ')';
    return out.str();
}

} // namespace

void Mesh::validate(const std::string& source) const {
    if (indices.size() % 3 != 0) {
        throw InputError(source, 0, "the mesh has " + std::to_string(indices.size()) +
                                        " indices; a triangle list needs a multiple of 3");
    }
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= vertices.size()) {
            throw InputError(source, 0, "triangle " + std::to_string(i / 3) + " refers to vertex " +
                                            std::to_string(indices[i]) + " but the mesh has only " +
                                            std::to_string(vertices.size()) + " vertices");
        }
    }
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vertex& vertex = vertices[i];
        auto reject = [&](const char* attribute, const std::string& value) {
            throw InputError(source, 0, "vertex " + std::to_string(i) + " has a " + attribute +
                                            " that is not finite: " + value);
        };
        if (!isFinite(vertex.position)) reject("position", describe(vertex.position));
        if (!isFinite(vertex.normal)) reject("normal", describe(vertex.normal));
        if (!isFinite(vertex.uv)) reject("uv", describe(vertex.uv));
        if (!isFinite(vertex.tangent)) reject("tangent", describe(vertex.tangent));
    }
}

// The cross product of two edges of a triangle has the length of twice the
// triangle's area, so summing the un-normalized cross products weighs each
// face by its area: a sliver triangle barely tilts the normal of the corner it
// shares with a large one. See the mesh page of the docs (lab 03) for the
// comparison with angle-weighted normals.
void computeSmoothNormals(Mesh& mesh) {
    STOA_ASSERT(mesh.indices.size() % 3 == 0,
                "computeSmoothNormals(): the index count is not a multiple of 3. Call Mesh::validate() first.");
    std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        STOA_ASSERT(i0 < sums.size() && i1 < sums.size() && i2 < sums.size(),
                    "computeSmoothNormals(): an index is out of range. Call Mesh::validate() first.");
        const glm::vec3 p0 = mesh.vertices[i0].position;
        const glm::vec3 faceNormal =
            glm::cross(mesh.vertices[i1].position - p0, mesh.vertices[i2].position - p0);  // length = 2 * area
        sums[i0] += faceNormal;
        sums[i1] += faceNormal;
        sums[i2] += faceNormal;
    }
    bool exact = true;
    for (std::size_t i = 0; i < sums.size(); ++i) {
        const float length = glm::length(sums[i]);
        const bool usable = length > 0.0f && std::isfinite(length);
        // A sum past float's range (a huge triangle: its cross product
        // overflows) or lost to underflow (a tiny one): redo it in double.
        if (!usable || length < 1e-18f) exact = false;
        mesh.vertices[i].normal = usable ? sums[i] / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    if (exact) return;
    // The same sums in double, where float positions cannot overflow a cross
    // product (2 * 3.4e38^2 is far below 1.8e308) nor underflow one. Only
    // meshes that need it take this path, so the normals of every other mesh
    // keep their float bits.
    std::vector<glm::dvec3> wide(mesh.vertices.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
        const glm::dvec3 p0(mesh.vertices[i0].position);
        const glm::dvec3 faceNormal =
            glm::cross(glm::dvec3(mesh.vertices[i1].position) - p0, glm::dvec3(mesh.vertices[i2].position) - p0);
        wide[i0] += faceNormal;
        wide[i1] += faceNormal;
        wide[i2] += faceNormal;
    }
    for (std::size_t i = 0; i < wide.size(); ++i) {
        const float length = glm::length(sums[i]);
        if (length > 0.0f && std::isfinite(length) && length >= 1e-18f) continue;  // exact in float already
        const double wideLength = glm::length(wide[i]);
        const bool usable = wideLength > 0.0 && std::isfinite(wideLength);
        mesh.vertices[i].normal = usable ? glm::vec3(wide[i] / wideLength) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

} // namespace stoa
