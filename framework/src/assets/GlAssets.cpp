#include <stoa/assets/GlAssets.hpp>

#include <stoa/core/InputFile.hpp>
#include <stoa/geometry/ObjLoader.hpp>

#include <map>
#include <sstream>
#include <system_error>

namespace fs = std::filesystem;

namespace stoa {

namespace {

/// The lines of `text`, without empty ones.
std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty()) lines.push_back(line);
    }
    return lines;
}

fs::path withExtension(const fs::path& path, const char* extension) {
    fs::path file = path;
    file += extension;
    return file;
}

} // namespace

AssetLoader<Texture2D> textureLoader(TextureOptions options) {
    return [options](const fs::path& path) {
        LoadedAsset<Texture2D> loaded;
        loaded.asset = std::make_shared<const Texture2D>(Texture2D::fromFile(path, options));
        loaded.files = {path};
        return loaded;
    };
}

AssetLoader<Program> programLoader(std::vector<fs::path> searchPath) {
    return [searchPath](const fs::path& path) {
        const fs::path geometry = withExtension(path, ".geom");
        std::error_code error;
        Program program = fs::exists(geometry, error)
                              ? Program::fromFiles(withExtension(path, ".vert"), geometry, withExtension(path, ".frag"),
                                                   searchPath)
                              : Program::fromFiles(withExtension(path, ".vert"), withExtension(path, ".frag"), searchPath);
        LoadedAsset<Program> loaded;
        loaded.files = program.files();
        // A .geom file added later is a reason to load again: watch where it would be.
        loaded.files.push_back(geometry);
        loaded.asset = std::make_shared<const Program>(std::move(program));
        return loaded;
    };
}

AssetLoader<GpuModel> gpuModelLoader(std::function<void(Mesh&)> meshFilter) {
    return [meshFilter](const fs::path& path) {
        LoadedAsset<GpuModel> loaded;
        loaded.files = {path};
        // Read as loadObj() does, noting each MTL file on the way.
        const MtlReader readMtl = [&loaded](const fs::path& mtlPath) {
            loaded.files.push_back(mtlPath);
            return readInputFile(mtlPath, maxMtlFileBytes, "an MTL file");
        };
        std::ostringstream warnings;
        const Model model =
            parseObj(readInputFile(path, maxObjFileBytes, "an OBJ file"), path, readMtl, warnings);
        loaded.warnings = linesOf(warnings.str());

        // Each map file once, however many parts name it.
        std::map<std::string, std::shared_ptr<const Texture2D>> maps;
        const auto map = [&](const std::string& file) -> std::shared_ptr<const Texture2D> {
            if (file.empty()) return nullptr;
            auto& texture = maps[file];
            if (!texture) {
                texture = std::make_shared<const Texture2D>(Texture2D::fromFile(file));
                loaded.files.push_back(file);
            }
            return texture;
        };
        auto gpuModel = std::make_shared<GpuModel>();
        for (const ModelPart& part : model.parts) {
            GpuModelPart gpuPart;
            if (meshFilter) {
                Mesh mesh = part.mesh;
                meshFilter(mesh);
                gpuPart.mesh = std::make_shared<const GpuMesh>(mesh);
            } else {
                gpuPart.mesh = std::make_shared<const GpuMesh>(part.mesh);
            }
            gpuPart.material = part.material;
            gpuPart.diffuseMap = map(part.material.diffuseMap);
            gpuPart.specularMap = map(part.material.specularMap);
            gpuPart.normalMap = map(part.material.normalMap);
            gpuPart.heightMap = map(part.material.heightMap);
            gpuModel->parts.push_back(std::move(gpuPart));
        }
        loaded.asset = std::move(gpuModel);
        return loaded;
    };
}

void addGlAssetLoaders(AssetCache& cache, std::vector<fs::path> shaderSearchPath, std::function<void(Mesh&)> meshFilter) {
    cache.setLoader<Texture2D>(textureLoader());
    cache.setLoader<Program>(programLoader(std::move(shaderSearchPath)));
    cache.setLoader<GpuModel>(gpuModelLoader(std::move(meshFilter)));
}

} // namespace stoa
