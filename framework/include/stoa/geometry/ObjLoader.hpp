#pragma once
// Loading Wavefront OBJ models (with their MTL materials) into CPU meshes.

#include <stoa/geometry/Material.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <iosfwd>
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

/// Limits of loadObj(), checked before the work they bound.
inline constexpr std::size_t maxObjFileBytes = 256u << 20;  // 256 MiB read at most from an OBJ file
inline constexpr std::size_t maxMtlFileBytes = 16u << 20;   // 16 MiB from each MTL file
/// A convex face may have any number of corners (it becomes a fan, in linear
/// time); a non-convex one at most this many (ear clipping is quadratic).
inline constexpr int maxNonConvexFaceCorners = 64;

/// Loads a Wavefront OBJ file and the MTL files it names.
///
/// - Positions, normals and uvs as written (uvs are zero where a face gives
///   none). Normals from the file are normalized (a huge one like
///   "vn 3e38 3e38 3e38" too). Where the file gives no normal, or gives
///   "vn 0 0 0", the vertex gets a smooth normal: the normalized,
///   area-weighted sum of the normals of the faces that share its position
///   (computeSmoothNormals, exact for huge and tiny triangles alike).
///   Smoothing groups are ignored.
/// - Faces keep their winding: a triangle as it is; a quad split along its
///   shorter diagonal; a convex polygon (within 1e-4 of its extent) as a fan
///   from its first corner; a
///   non-convex polygon of up to maxNonConvexFaceCorners corners by ear
///   clipping. No face vanishes: a polygon that repeats a vertex is an error.
/// - Within a part, OBJ corners with the same (position, normal, uv) indices
///   become one vertex.
/// - Text: UTF-8 (a byte-order mark is skipped), lines ending in LF, CR LF or
///   a lone CR. UTF-16 is refused with a message that says so.
/// - Materials: Ka, Kd, Ks, Ns, map_Kd, map_Ks, norm (normal map) and
///   map_bump / bump (height map, with its -bm multiplier as bumpScale); a
///   value the MTL leaves out keeps the Material default; texture paths are
///   made absolute, relative to the folder of the MTL file that names them.
///   newmtl and usemtl names are the rest of the line (spaces included).
///   Colours outside [0, 1] are clamped and a negative Ns becomes 0, each
///   with a warning on `warnings` naming the MTL file and line.
///   Texture options (-o, -s, -clamp, ...) other than -bm are read past and
///   ignored. Other maps (map_Ka, map_d, disp, ...) are ignored.
/// - Only regular files are read (a FIFO, a device such as /dev/zero or a
///   folder is refused, for the OBJ and for every mtllib), at most
///   maxObjFileBytes and maxMtlFileBytes. Memory grows with the file: at
///   worst about 100 bytes per byte of OBJ text (a 1 MB file needs at most
///   about 100 MB), whatever the file holds.
///
/// Throws InputError naming the file (the OBJ, or the MTL) and the line for:
/// a file that cannot be read (and why: missing, a folder, a FIFO, a device,
/// a symbolic link loop, too large); a face index that is 0 or refers to a
/// position, uv or normal not defined before that line (negative, relative
/// indices and numbers too large for any index included); a face with fewer
/// than 3 vertices, or one that repeats a vertex; a non-convex face with more
/// than maxNonConvexFaceCorners corners; a number that is malformed, NaN or
/// infinite; an mtllib file that cannot be read; a usemtl naming a material
/// no earlier mtllib defined; (naming the MTL file and line) a texture file
/// that does not exist, a map statement without a file name, an unknown
/// texture option or one with too few values; UTF-16 text (line 0); and
/// (line 0) a file without any face.
[[nodiscard]] Model loadObj(const std::filesystem::path& path, std::ostream& warnings);
/// The same, warnings on std::cerr.
[[nodiscard]] Model loadObj(const std::filesystem::path& path);

/// Gives the text of the MTL file at a path (loadObj reads it from disk with
/// maxMtlFileBytes); throws InputError when it cannot.
using MtlReader = std::function<std::string(const std::filesystem::path& mtlPath)>;

/// What loadObj() does once it has read the OBJ file: `text` is the file's
/// content, `path` where it lives (MTL files are looked for next to it).
/// For tests and fuzzers, which supply MTL text without files.
[[nodiscard]] Model parseObj(const std::string& text, const std::filesystem::path& path, const MtlReader& readMtl,
                             std::ostream& warnings);

} // namespace stoa
