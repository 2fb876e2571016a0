#pragma once
// What an editor scene's names stand for, on the GPU: meshes ("shape:cube" or
// an OBJ file), textures and programs, looked up in the scene file's folder
// first and then in assets/ (programs: in shaders/), loaded once through
// AssetCaches and reloaded when their files change on disk. A program whose
// fragment stage was edited in the shader panel draws as its LiveShader
// instead. A name that does not load is logged once and drawn without (a
// texture), with the default program (a program) or not at all (a mesh).
//
//   EditorAssets assets;                               // a GL context is current
//   assets.setReloadDispatch(assetsToReload);          // lab 11's
//   assets.setSceneFolder(sceneFile.parent_path());
//   each frame: assets.update(seconds); for (auto& line : assets.takeLog()) ...
//   for (const GpuMesh* mesh : assets.meshes(object.mesh)) mesh->draw();

#include <stoa/assets/AssetCache.hpp>
#include <stoa/assets/DataAssets.hpp>
#include <stoa/assets/GlAssets.hpp>
#include <stoa/editor/LiveShader.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace stoa {

class EditorAssets {
public:
    /// The built-in shapes are uploaded here: needs a current context.
    EditorAssets();
    ~EditorAssets();

    /// Names are looked up in `folder` (the scene file's) before assets/.
    void setSceneFolder(const std::filesystem::path& folder);
    /// Who decides which changed assets reload (AssetCache::setReloadDispatch).
    void setReloadDispatch(ReloadDispatch dispatch);
    /// Runs on every mesh (shapes and OBJ parts) before upload, from now on:
    /// the editor's lab-04 tangents for normal maps. The shapes are made again
    /// and the models loaded so far are loaded again when next asked for.
    void setMeshFilter(std::function<void(Mesh&)> filter);
    /// Polls the files and reloads what the dispatch says is due.
    void update(double now);
    /// Log lines since the last call: reloads, failures, names that did not load.
    std::vector<std::string> takeLog();

    /// An asset the scene names that did not load: its name as the scene
    /// writes it, and why (the logged line).
    struct Failure {
        std::string name;
        std::string message;
    };
    /// Every asset that did not load so far, in the order they failed (a
    /// picture made from the command line stops at the first: stoa-editor --render).
    const std::vector<Failure>& failures() const { return m_failures; }

    /// The shapes' names, in the order an asset browser lists them.
    static const std::vector<std::string>& shapeNames();
    /// The shape called `name` as a mesh on the CPU, as meshes() draws it (for
    /// code that needs its triangles: the ball's BVH); nullopt for other names.
    static std::optional<Mesh> shapeMesh(const std::string& name);
    /// The OBJ files under assets/ (names relative to it), for an asset browser.
    std::vector<std::string> modelNames() const;

    /// The meshes that draw `name`: one for a shape, one per material for an
    /// OBJ model; none when it does not load (logged once).
    std::vector<const GpuMesh*> meshes(const std::string& name);
    /// The texture `name`; nullptr for "" or when it does not load (logged once).
    const Texture2D* texture(const std::string& name);
    /// A crowd world (lab 10's XML) by name: next to the scene file, under
    /// assets/, or under assets/crowds/ ("mars_explorers.xml"); a new version
    /// when the world file, a file it includes or a ground map changes. nullptr
    /// for "" or when it does not load (logged once).
    const AssetRef<CrowdWorld>* crowdWorld(const std::string& name);
    /// The program `name` ("editor/lit": editor/lit.vert + editor/lit.frag in
    /// shaders/); "" and names that do not load: editor/lit. Its uniform block
    /// Frame is bound to FrameUniforms::kBinding.
    const Program& program(const std::string& name);
    /// The live shader of program `name` (made at the first call, from its files):
    /// the shader panel edits it, and program(name) draws with it from then on.
    LiveShader& liveShader(const std::string& name);
    bool hasLiveShader(const std::string& name) const { return m_live.count(name) != 0; }
    /// Forgets the live shader of `name`: program(name) is its files' program
    /// again (reloaded when they change).
    void dropLiveShader(const std::string& name) { m_live.erase(name); }
    /// How often the program `name` was loaded from its files (1 after the
    /// first load, one more per reload; 0 before it was loaded).
    int programVersion(const std::string& name) const;
    /// The text of program `name`'s fragment file, as it is on disk now.
    static std::string fragmentFileText(const std::string& name);

    static constexpr const char* kDefaultProgram = "editor/lit";

private:
    AssetCache& cacheFor(const std::string& name);
    void failedOnce(const std::string& name, const std::string& message);

    std::vector<Failure> m_failures;
    std::map<std::string, std::shared_ptr<const GpuMesh>> m_shapes;
    std::unique_ptr<AssetCache> m_assets;    // assets/
    std::unique_ptr<AssetCache> m_scene;     // the scene file's folder (none until set)
    std::unique_ptr<AssetCache> m_shaders;   // shaders/
    std::map<std::string, AssetRef<GpuModel>> m_models;
    std::map<std::string, AssetRef<CrowdWorld>> m_worlds;
    std::map<std::string, AssetRef<Texture2D>> m_textures;
    std::map<std::string, AssetRef<Program>> m_programs;
    std::map<std::string, std::pair<GLuint, int>> m_boundBlocks;   // program name -> the id/generation bound
    std::map<std::string, std::unique_ptr<LiveShader>> m_live;
    std::set<std::string> m_failed;
    std::vector<std::string> m_log;
    ReloadDispatch m_dispatch;
    std::function<void(Mesh&)> m_meshFilter;
    void makeShapes();
    void addLoaders(AssetCache& cache) const;
};

} // namespace stoa
