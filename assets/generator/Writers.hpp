#pragma once
// Writing the generated assets: OBJ meshes and image files. Every writer gives
// the same bytes for the same input (the tests compare them with the committed
// files). Failures throw InputError naming the file.

#include <stoa/geometry/Mesh.hpp>
#include <stoa/image/Image.hpp>

#include <filesystem>
#include <string>

namespace stoa::assets {

/// What an OBJ file gets besides positions and faces.
struct ObjOptions {
    std::string objectName;     // the `o` statement
    std::string materialLibrary; // `mtllib`; empty for none
    std::string materialName;    // `usemtl`; empty for none
    bool writeNormals = true;    // false: faces name only positions (and uvs), the reader computes normals
    bool writeUvs = true;
};

/// Writes `mesh` as an OBJ: positions, uvs and normals each listed once (equal
/// values, as printed with 4 decimals, share one index), then one `f` per triangle.
void writeObj(const std::filesystem::path& path, const Mesh& mesh, const ObjOptions& options);

/// Image files through stb_image_write (PNG, 24-bit BMP, JPG at `quality`,
/// TGA with RLE) and by hand (binary PGM, "P5", for a 1-channel image).
void writePng(const std::filesystem::path& path, const Image& image);
void writeBmp(const std::filesystem::path& path, const Image& image);
void writeJpg(const std::filesystem::path& path, const Image& image, int quality);
void writeTga(const std::filesystem::path& path, const Image& image);
void writePgm(const std::filesystem::path& path, const Image& image);

/// Writes `text` to `path` as is.
void writeText(const std::filesystem::path& path, const std::string& text);

} // namespace stoa::assets
