#include <stoa/assets/DataAssets.hpp>

#include <stoa/crowd/CrowdXml.hpp>

#include <pugixml.hpp>

#include <set>

namespace fs = std::filesystem;

namespace stoa {

namespace {

/// Adds the files `file` includes, and theirs, to `files`. Runs after
/// loadCrowdWorld() succeeded, so the includes are known to be well formed,
/// within the depth limit and free of loops; the checks here only keep a file
/// changed in between from sending it round in circles.
void addIncludes(const fs::path& file, std::set<std::string>& seen, std::vector<fs::path>& files, int depth) {
    if (depth > CrowdXmlLimits::maxIncludeDepth || !seen.insert(file.lexically_normal().string()).second) return;
    files.push_back(file);
    pugi::xml_document document;
    if (!document.load_file(file.c_str())) return;
    for (const pugi::xml_node include : document.document_element().children("include")) {
        const fs::path included = file.parent_path() / include.attribute("file").value();
        addIncludes(included, seen, files, depth + 1);
    }
}

} // namespace

AssetLoader<Md2Model> md2Loader() {
    return [](const fs::path& path) {
        LoadedAsset<Md2Model> loaded;
        loaded.asset = std::make_shared<const Md2Model>(loadMd2(path));
        loaded.files = {path};
        return loaded;
    };
}

AssetLoader<CrowdWorld> crowdWorldLoader() {
    return [](const fs::path& path) {
        LoadedAsset<CrowdWorld> loaded;
        auto world = std::make_shared<const CrowdWorld>(loadCrowdWorld(path));
        std::set<std::string> seen;
        addIncludes(path, seen, loaded.files, 0);
        if (!world->ground.collisionMap.empty()) loaded.files.push_back(world->ground.collisionMap);
        if (!world->ground.heightMap.empty()) loaded.files.push_back(world->ground.heightMap);
        loaded.asset = std::move(world);
        return loaded;
    };
}

void addDataAssetLoaders(AssetCache& cache) {
    cache.setLoader<Md2Model>(md2Loader());
    cache.setLoader<CrowdWorld>(crowdWorldLoader());
}

} // namespace stoa
