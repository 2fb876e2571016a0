#pragma once
// Assets by name, loaded once, loaded again when their files change on disk.
// A name is the asset's path under the cache's root folder; with the
// repository's root (paths::sourceDir()):
//   "assets/acropolis/column_diffuse.png"   a Texture2D
//   "shaders/basic/lit"                     a Program: shaders/basic/lit.vert + .frag
//   "assets/acropolis/column.obj"           a GpuModel (with its MTL files and maps)
//   "assets/crowds/explorer.md2"            an Md2Model
//   "assets/crowds/mars_explorers.xml"      a CrowdWorld (with the files it includes)
//
//   AssetCache cache(paths::sourceDir());
//   addGlAssetLoaders(cache, {paths::shadersDir()});      // GlAssets.hpp: textures, programs, models
//   addDataAssetLoaders(cache);                           // DataAssets.hpp: MD2 models, crowd worlds
//   cache.setReloadDispatch(assetsToReload);              // lab 11; without it, reloads at once
//   AssetRef<Texture2D> marble = cache.get<Texture2D>("assets/acropolis/column_diffuse.png");
//   each frame:
//     cache.update(secondsSinceStart);
//     for (const std::string& line : cache.takeLog()) std::cout << line << '\n';
//     marble->bind(0);                                     // the newest good version
//
// A kind of asset is a C++ type with a loader (setLoader<T>()) that loads it
// from the path root/name and lists every file it read. The cache watches
// those files (FileWatcher); update() asks the reload dispatch which assets
// are due and loads them again. A reload that fails (a broken PNG, a shader
// that does not compile, bad XML) keeps the last good version, and the log
// says why (file:line: message); the next good save replaces it.
//
// The cache itself needs no OpenGL; loaders of GL objects do, so get() and
// update() must run with the context current that the assets belong to.
// One thread: the cache is not meant to be shared between threads.

#include <stoa/assets/FileWatcher.hpp>
#include <stoa/assets/ReloadPlan.hpp>
#include <stoa/core/Assert.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <typeindex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace stoa {

/// What a loader returns: the asset and every file it read to make it.
template <typename T>
struct LoadedAsset {
    std::shared_ptr<const T> asset;
    std::vector<std::filesystem::path> files; // the asset's own file(s) first
    std::vector<std::string> warnings;        // shown in the cache's log, e.g. an MTL colour clamped
};

/// Loads an asset of kind T from `path` (the cache's root / the name). Throws
/// InputError naming the file and line when the input is bad.
template <typename T>
using AssetLoader = std::function<LoadedAsset<T>(const std::filesystem::path& path)>;

namespace detail {
template <typename T>
struct AssetSlot {
    std::string name;
    std::shared_ptr<const T> current;
    int version = 0;
};
} // namespace detail

/// A handle to a cached asset that always yields its newest good version.
/// Cheap to copy; stays valid after the cache is gone (with the version it had).
template <typename T>
class AssetRef {
public:
    /// No asset.
    AssetRef() = default;

    const T& operator*() const { return *current(); }
    const T* operator->() const { return current().get(); }
    /// The version now; holding it keeps that version alive across reloads.
    const std::shared_ptr<const T>& current() const {
        STOA_ASSERT(m_slot, "AssetRef::current(): an empty AssetRef. Get one from AssetCache::get<T>(name).");
        return m_slot->current;
    }
    /// 1 after the first load, one more after each successful reload.
    int version() const { return m_slot ? m_slot->version : 0; }
    const std::string& name() const {
        STOA_ASSERT(m_slot, "AssetRef::name(): an empty AssetRef. Get one from AssetCache::get<T>(name).");
        return m_slot->name;
    }
    explicit operator bool() const { return m_slot != nullptr; }

private:
    friend class AssetCache;
    explicit AssetRef(std::shared_ptr<const detail::AssetSlot<T>> slot) : m_slot(std::move(slot)) {}
    std::shared_ptr<const detail::AssetSlot<T>> m_slot;
};

struct AssetCacheOptions {
    double debounceSeconds = 0.2;                              // handed to the reload dispatch
    FileWatcher::Backend watcher = FileWatcher::Backend::Automatic;
};

class AssetCache {
public:
    /// Names are paths under `root`. No file is read yet.
    explicit AssetCache(std::filesystem::path root, AssetCacheOptions options = {});

    /// The loader of kind T (replacing an earlier one); assets loaded already keep theirs.
    template <typename T>
    void setLoader(AssetLoader<T> loader) {
        m_loaders[std::type_index(typeid(T))] = std::make_shared<AssetLoader<T>>(std::move(loader));
    }

    /// The asset `name` of kind T, loaded now unless the cache has it. Throws
    /// InputError when the first load fails (then the cache keeps nothing of
    /// it). Asserts that T has a loader and that `name` is not cached as
    /// another kind.
    template <typename T>
    [[nodiscard]] AssetRef<T> get(const std::string& name);

    /// Who decides which assets are due (lab 11's assetsToReload()). Without
    /// one (or with an empty function), every asset with a file changed after
    /// it was loaded is loaded again at the next update(), without debounce.
    void setReloadDispatch(ReloadDispatch dispatch) { m_dispatch = std::move(dispatch); }

    /// Collects the file changes since the last update, asks the dispatch which
    /// assets are due, and loads them again. `now`: seconds on a clock that
    /// goes forward between updates (e.g. wall time since the program started;
    /// not a simulation time that can pause); changes are stamped with it.
    void update(double now);

    /// The log lines since the last call, oldest first: "reloaded NAME",
    /// "cannot reload NAME, keeping the last good version: FILE:LINE: ...",
    /// loader warnings and the watcher's own lines.
    [[nodiscard]] std::vector<std::string> takeLog();

    /// Why the last reload of `name` failed; empty when it succeeded (or the
    /// cache has no such asset).
    std::string errorOf(const std::string& name) const;

    /// The cache's assets in the order they were first loaded, as the dispatch sees them.
    std::vector<AssetFiles> assets() const;
    /// The file changes the cache holds on to (those the dispatch may still need).
    const std::vector<FileChange>& pendingChanges() const { return m_changes; }

    const std::filesystem::path& root() const { return m_root; }
    /// root()/name, lexically normal.
    std::filesystem::path pathOf(const std::string& name) const;
    double debounceSeconds() const { return m_options.debounceSeconds; }
    bool contains(const std::string& name) const { return m_index.count(name) != 0; }

    /// What update() does without a dispatch: the names of the assets with a
    /// change to one of their files later than their loadedAt, in the order of `assets`.
    static std::vector<std::string> changedSinceLoaded(const std::vector<FileChange>& changes,
                                                       const std::vector<AssetFiles>& assets);

private:
    struct Entry {
        std::type_index kind;
        AssetFiles files;                  // name, files, loadedAt
        std::string error;                 // of the last reload; empty when it succeeded
        std::shared_ptr<void> slot;        // the detail::AssetSlot<T>
        /// Loads the asset again into its slot; returns its files and warnings. Throws on failure.
        std::function<std::pair<std::vector<std::filesystem::path>, std::vector<std::string>>()> reload;
    };

    /// Adds an entry (its files watched) after a successful first load.
    void add(Entry entry, const std::vector<std::filesystem::path>& files, const std::vector<std::string>& warnings);
    void reload(Entry& entry, double now);
    void setFiles(Entry& entry, const std::vector<std::filesystem::path>& files);
    void pruneChanges();

    std::filesystem::path m_root;
    AssetCacheOptions m_options;
    FileWatcher m_watcher;
    ReloadDispatch m_dispatch;
    std::unordered_map<std::type_index, std::shared_ptr<void>> m_loaders; // AssetLoader<T> by T
    std::vector<Entry> m_entries;                                         // in the order first loaded
    std::map<std::string, std::size_t> m_index;                          // name -> index into m_entries
    std::vector<FileChange> m_changes;                                    // seen, maybe still needed
    std::vector<std::string> m_log;
    double m_now = 0.0;                                                   // the last update's time
};

template <typename T>
AssetRef<T> AssetCache::get(const std::string& name) {
    const auto found = m_index.find(name);
    if (found != m_index.end()) {
        Entry& entry = m_entries[found->second];
        STOA_ASSERT(entry.kind == std::type_index(typeid(T)),
                    "AssetCache::get<T>(): the name is cached as another kind of asset. "
                    "Ask for it with the type it was first loaded as.");
        return AssetRef<T>(std::static_pointer_cast<const detail::AssetSlot<T>>(entry.slot));
    }
    const auto loaderEntry = m_loaders.find(std::type_index(typeid(T)));
    STOA_ASSERT(loaderEntry != m_loaders.end(),
                "AssetCache::get<T>(): no loader for this kind of asset. Call setLoader<T>() first "
                "(addGlAssetLoaders() and addDataAssetLoaders() add the framework's kinds).");
    const auto loader = std::static_pointer_cast<AssetLoader<T>>(loaderEntry->second);
    const std::filesystem::path path = pathOf(name);

    LoadedAsset<T> loaded = (*loader)(path); // throws: nothing is cached
    STOA_ASSERT(loaded.asset, "AssetCache::get<T>(): the loader returned no asset. A loader throws InputError "
                              "when it cannot load, or returns the asset.");
    auto slot = std::make_shared<detail::AssetSlot<T>>();
    slot->name = name;
    slot->current = std::move(loaded.asset);
    slot->version = 1;

    Entry entry{std::type_index(typeid(T)), {}, {}, slot, {}};
    entry.files.name = name;
    entry.reload = [slot, loader, path]() {
        LoadedAsset<T> again = (*loader)(path);
        STOA_ASSERT(again.asset, "AssetCache::update(): a loader returned no asset. A loader throws InputError "
                                 "when it cannot load, or returns the asset.");
        slot->current = std::move(again.asset);
        ++slot->version;
        return std::make_pair(std::move(again.files), std::move(again.warnings));
    };
    add(std::move(entry), loaded.files, loaded.warnings);
    return AssetRef<T>(std::move(slot));
}

} // namespace stoa
