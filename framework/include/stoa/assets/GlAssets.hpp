#pragma once
// The asset kinds that are OpenGL objects: textures, programs and OBJ models
// on the GPU. Loading them needs the context current that will draw them.
//
//   AssetCache cache(paths::sourceDir());
//   addGlAssetLoaders(cache, {paths::shadersDir()});
//   AssetRef<Program> lit = cache.get<Program>("shaders/basic/lit");    // lit.vert + lit.frag
//   AssetRef<GpuModel> column = cache.get<GpuModel>("assets/acropolis/column.obj");

#include <stoa/assets/AssetCache.hpp>
#include <stoa/geometry/Material.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/Texture2D.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

namespace stoa {

/// One material's faces of an OBJ model, uploaded, with the maps its material names.
struct GpuModelPart {
    std::shared_ptr<const GpuMesh> mesh;             // object space of the OBJ file
    Material material;                               // as read from the MTL file
    std::shared_ptr<const Texture2D> diffuseMap;     // null when the material names none
    std::shared_ptr<const Texture2D> specularMap;
    std::shared_ptr<const Texture2D> normalMap;
    std::shared_ptr<const Texture2D> heightMap;
};

/// An OBJ model on the GPU: one part per material (loadObj()'s order).
struct GpuModel {
    std::vector<GpuModelPart> parts;
};

/// Texture2D::fromFile(path, options); its one file.
AssetLoader<Texture2D> textureLoader(TextureOptions options = {});

/// A program named by its files without their extension: path.vert and
/// path.frag, with path.geom between them when that file exists. Includes are
/// looked up as ShaderSource::load() does, in `searchPath` after the folder of
/// the including file. Its files are Program::files() (the includes too). A
/// stage that does not compile is a ShaderError naming the file and line.
AssetLoader<Program> programLoader(std::vector<std::filesystem::path> searchPath);

/// loadObj(path) with its parts uploaded and their maps loaded (as textureLoader()
/// with default options; not shared with TextureCache, which would hand back the
/// old texture of a changed file). Its files: the OBJ file, its MTL files and
/// their maps. loadObj's warnings go to the cache's log. `meshFilter`, when
/// set, changes each part's mesh before upload (the editor's lab-04 tangents).
AssetLoader<GpuModel> gpuModelLoader(std::function<void(Mesh&)> meshFilter = {});

/// Sets the three loaders on `cache`.
void addGlAssetLoaders(AssetCache& cache, std::vector<std::filesystem::path> shaderSearchPath,
                       std::function<void(Mesh&)> meshFilter = {});

} // namespace stoa
