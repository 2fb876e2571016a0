#include <stoa/editor/EditorAssets.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/render/FrameUniforms.hpp>

#include <algorithm>

namespace stoa {

namespace fs = std::filesystem;

EditorAssets::EditorAssets()
    : m_assets(std::make_unique<AssetCache>(paths::assetsDir())),
      m_shaders(std::make_unique<AssetCache>(paths::shadersDir())) {
    addLoaders(*m_assets);
    addLoaders(*m_shaders);
    makeShapes();
}

void EditorAssets::addLoaders(AssetCache& cache) const {
    addGlAssetLoaders(cache, {paths::shadersDir()}, m_meshFilter);
    addDataAssetLoaders(cache);
}

std::optional<Mesh> EditorAssets::shapeMesh(const std::string& name) {
    if (name == "shape:cube") return shapes::cube(1.0f);
    if (name == "shape:sphere") return shapes::sphere(0.5f, 32, 16);
    if (name == "shape:cylinder") return shapes::cylinder(0.5f, 1.0f, 32);
    if (name == "shape:plane") return shapes::plane(1.0f, 1);
    return std::nullopt;
}

void EditorAssets::makeShapes() {
    for (const std::string& name : shapeNames()) {
        Mesh mesh = *shapeMesh(name);
        if (m_meshFilter) m_meshFilter(mesh);
        m_shapes[name] = std::make_shared<GpuMesh>(mesh);
    }
}

void EditorAssets::setMeshFilter(std::function<void(Mesh&)> filter) {
    m_meshFilter = std::move(filter);
    // The models loaded so far went through the old filter: fresh caches for
    // assets/ and the scene's folder load them again (textures and worlds too,
    // when next asked for); the programs' cache stays.
    m_models.clear();
    m_textures.clear();
    m_worlds.clear();
    m_failed.clear();
    m_assets = std::make_unique<AssetCache>(paths::assetsDir());
    addLoaders(*m_assets);
    if (m_scene) {
        const fs::path folder = m_scene->root();
        m_scene = std::make_unique<AssetCache>(folder);
        addLoaders(*m_scene);
    }
    addLoaders(*m_shaders);
    if (m_dispatch) setReloadDispatch(m_dispatch);
    makeShapes();
}

EditorAssets::~EditorAssets() = default;

void EditorAssets::setSceneFolder(const fs::path& folder) {
    std::error_code error;
    const fs::path absolute = fs::absolute(folder, error).lexically_normal();
    if (error || fs::equivalent(absolute, paths::assetsDir(), error)) {
        m_scene.reset();
        return;
    }
    m_scene = std::make_unique<AssetCache>(absolute);
    addLoaders(*m_scene);
    if (m_dispatch) m_scene->setReloadDispatch(m_dispatch);
}

void EditorAssets::setReloadDispatch(ReloadDispatch dispatch) {
    m_dispatch = std::move(dispatch);
    for (AssetCache* cache : {m_assets.get(), m_scene.get(), m_shaders.get()})
        if (cache) cache->setReloadDispatch(m_dispatch);
}

void EditorAssets::update(double now) {
    for (AssetCache* cache : {m_assets.get(), m_scene.get(), m_shaders.get()}) {
        if (!cache) continue;
        cache->update(now);
        for (std::string& line : cache->takeLog()) m_log.push_back(std::move(line));
    }
}

std::vector<std::string> EditorAssets::takeLog() {
    std::vector<std::string> lines;
    lines.swap(m_log);
    return lines;
}

const std::vector<std::string>& EditorAssets::shapeNames() {
    static const std::vector<std::string> names = {"shape:cube", "shape:sphere", "shape:cylinder", "shape:plane"};
    return names;
}

std::vector<std::string> EditorAssets::modelNames() const {
    std::vector<std::string> names;
    std::error_code error;
    for (fs::recursive_directory_iterator it(paths::assetsDir(), error), end; !error && it != end; it.increment(error))
        if (it->is_regular_file(error) && it->path().extension() == ".obj")
            names.push_back(it->path().lexically_relative(paths::assetsDir()).generic_string());
    std::sort(names.begin(), names.end());
    return names;
}

AssetCache& EditorAssets::cacheFor(const std::string& name) {
    std::error_code error;
    if (m_scene && fs::exists(m_scene->root() / name, error)) return *m_scene;
    return *m_assets;
}

namespace {

/// Whether an asset name stays inside the folders it is looked up in: not
/// absolute, no ".." that climbs out ("../../etc/passwd" is not an asset).
bool staysInside(const std::string& name) {
    const fs::path path = fs::path(name).lexically_normal();
    return !path.is_absolute() && !path.has_root_name() && (path.empty() || *path.begin() != "..");
}

std::string outsideMessage(const char* what, const std::string& name) {
    return std::string("cannot load the ") + what + " " + name +
           ": an asset name is a path inside the scene file's folder or assets/, not absolute and not climbing out with ..";
}

} // namespace

void EditorAssets::failedOnce(const std::string& name, const std::string& message) {
    if (!m_failed.insert(name).second) return;
    m_log.push_back(message);
    m_failures.push_back({name, message});
}

std::vector<const GpuMesh*> EditorAssets::meshes(const std::string& name) {
    if (const auto shape = m_shapes.find(name); shape != m_shapes.end()) return {shape->second.get()};
    auto model = m_models.find(name);
    if (model == m_models.end()) {
        if (m_failed.count(name) || name.rfind("shape:", 0) == 0) {
            failedOnce(name, "no mesh '" + name + "': shapes are shape:cube, shape:sphere, shape:cylinder, shape:plane");
            return {};
        }
        if (!staysInside(name)) {
            failedOnce(name, outsideMessage("mesh", name));
            return {};
        }
        try {
            model = m_models.emplace(name, cacheFor(name).get<GpuModel>(name)).first;
        } catch (const InputError& error) {
            failedOnce(name, std::string("cannot load the mesh ") + name + ": " + error.what());
            return {};
        }
    }
    std::vector<const GpuMesh*> meshes;
    for (const GpuModelPart& part : model->second->parts) meshes.push_back(part.mesh.get());
    if (meshes.empty()) failedOnce(name, "the mesh " + name + " has no triangles: is it an OBJ file?");
    return meshes;
}

const AssetRef<CrowdWorld>* EditorAssets::crowdWorld(const std::string& name) {
    if (name.empty()) return nullptr;
    auto world = m_worlds.find(name);
    if (world == m_worlds.end()) {
        if (m_failed.count(name)) return nullptr;
        if (!staysInside(name)) {
            failedOnce(name, outsideMessage("crowd world", name));
            return nullptr;
        }
        std::error_code error;
        const bool inCrowds = !fs::exists(m_assets->root() / name, error) && fs::exists(m_assets->root() / "crowds" / name, error);
        const std::string cached = inCrowds && !(m_scene && fs::exists(m_scene->root() / name, error)) ? "crowds/" + name : name;
        try {
            world = m_worlds.emplace(name, cacheFor(cached).get<CrowdWorld>(cached)).first;
        } catch (const InputError& bad) {
            failedOnce(name, std::string("cannot load the crowd world ") + name + ": " + bad.what());
            return nullptr;
        }
    }
    return &world->second;
}

const Texture2D* EditorAssets::texture(const std::string& name) {
    if (name.empty()) return nullptr;
    auto texture = m_textures.find(name);
    if (texture == m_textures.end()) {
        if (m_failed.count(name)) return nullptr;
        if (!staysInside(name)) {
            failedOnce(name, outsideMessage("texture", name));
            return nullptr;
        }
        try {
            texture = m_textures.emplace(name, cacheFor(name).get<Texture2D>(name)).first;
        } catch (const InputError& error) {
            failedOnce(name, std::string("cannot load the texture ") + name + ": " + error.what());
            return nullptr;
        }
    }
    return texture->second.current().get();
}

const Program& EditorAssets::program(const std::string& requested) {
    const std::string name = requested.empty() || m_failed.count(requested) ? kDefaultProgram : requested;
    const Program* program = nullptr;
    int generation = 0;
    if (const auto live = m_live.find(name); live != m_live.end()) {
        program = &live->second->program();
        generation = -live->second->generation();
    } else {
        auto cached = m_programs.find(name);
        if (cached == m_programs.end()) {
            try {
                cached = m_programs.emplace(name, m_shaders->get<Program>(name)).first;
            } catch (const InputError& error) {
                if (name == kDefaultProgram) throw;
                failedOnce(name, std::string("cannot load the program ") + name + ", drawing with " + kDefaultProgram +
                                     ": " + error.what());
                return this->program(kDefaultProgram);
            }
        }
        program = cached->second.current().get();
        generation = cached->second.version();
    }
    auto& bound = m_boundBlocks[name];
    if (bound != std::make_pair(program->id(), generation)) {
        program->bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);
        bound = {program->id(), generation};
    }
    return *program;
}

int EditorAssets::programVersion(const std::string& name) const {
    const auto cached = m_programs.find(name);
    return cached == m_programs.end() ? 0 : cached->second.version();
}

std::string EditorAssets::fragmentFileText(const std::string& name) {
    return readInputFile(paths::shadersDir() / (name + ".frag"), 1 << 20, "a fragment shader");
}

LiveShader& EditorAssets::liveShader(const std::string& requested) {
    const std::string name = requested.empty() ? kDefaultProgram : requested;
    auto live = m_live.find(name);
    if (live == m_live.end())
        live = m_live.emplace(name, std::make_unique<LiveShader>(name + ".vert", name + ".frag",
                                                                std::vector<fs::path>{paths::shadersDir()})).first;
    return *live->second;
}

} // namespace stoa
