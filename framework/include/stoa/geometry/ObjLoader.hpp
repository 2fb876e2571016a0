#pragma once
// Loading Wavefront OBJ models (with their MTL materials) into CPU meshes.

#include <stoa/geometry/Material.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace stoa {

/// The faces of a model that share one material.
struct ModelPart {
    Mesh mesh;          // object space of the OBJ file
    Material material;  // Material{} (name "default") for faces without usemtl
};

/// A loaded OBJ file: one part per material its faces use, in the order the
/// file first uses them.
struct Model {
    std::vector<ModelPart> parts;
    std::string source;  // the path the model was loaded from
};

/// Loads a Wavefront OBJ file and the MTL files it names, using tinyobjloader.
///
/// - Positions, normals and uvs as written (uvs are zero where a face gives
///   none). Where the file gives no normal, the vertex gets a smooth normal:
///   the normalized, area-weighted sum of the normals of the faces that share
///   its position. Normals from the file are normalized. Smoothing groups are
///   ignored.
/// - Faces with more than 3 vertices are triangulated; winding is kept.
/// - Within a part, OBJ corners with the same (position, normal, uv) indices
///   become one vertex.
/// - Materials: Ka, Kd, Ks, Ns, map_Kd, map_Ks, norm (normal map) and
///   map_bump / bump (height map, with its -bm multiplier as bumpScale); a
///   value the MTL leaves out keeps the Material default; texture paths are
///   made absolute, relative to the folder of the MTL file that names them.
///   Texture options (-o, -s, -clamp, ...) other than -bm are read past and
///   ignored. Other maps (map_Ka, map_d, disp, ...) are ignored.
///
/// Throws InputError naming the file (the OBJ, or the MTL) and the line for:
/// a file that cannot be read; a face index that is 0 or refers to a
/// position, uv or normal not defined before that line (negative, relative
/// indices included); a face with fewer than 3 vertices; a number that is
/// malformed, NaN or infinite; an mtllib file that does not exist; a usemtl
/// naming a material no earlier mtllib defined; (naming the MTL file and
/// line) a texture file that does not exist, a map statement without a file
/// name, an unknown texture option or one with too few values; a line
/// tinyobjloader rejects;
/// and (line 0) a file without any face.
[[nodiscard]] Model loadObj(const std::filesystem::path& path);

} // namespace stoa
