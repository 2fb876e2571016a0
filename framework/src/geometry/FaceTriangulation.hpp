#pragma once
// Internal to stoa_core: the corners of an OBJ face and how a face becomes
// triangles (ObjLoader.cpp reads the file, FaceTriangulation.cpp cuts faces).

#include <glm/vec3.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace stoa::detail {

/// An OBJ face corner: 0-based indices, -1 where the corner gives none.
struct Corner {
    int position, uv, normal;
    bool operator==(const Corner& other) const {
        return position == other.position && normal == other.normal && uv == other.uv;
    }
};

struct CornerHash {
    std::size_t operator()(const Corner& key) const {
        std::size_t hash = std::hash<int>()(key.position);
        hash = hash * 1000003u ^ std::hash<int>()(key.normal);
        return hash * 1000003u ^ std::hash<int>()(key.uv);
    }
};

/// Appends the triangles of one face (its corners in file order) to `out`,
/// keeping its winding: a triangle as it is; a quad split along its shorter
/// diagonal (as tinyobjloader did, so that models render as before); a
/// convex polygon as a fan from its first corner (linear time, any number of
/// corners); a non-convex one by ear clipping, up to maxNonConvexFaceCorners
/// corners. Throws InputError(file, line, ...) for a polygon that repeats a
/// vertex and for a non-convex one past the cap.
void triangulate(const std::vector<Corner>& face, const std::vector<glm::vec3>& positions, std::vector<Corner>& out,
                 const std::string& file, int line);

} // namespace stoa::detail
