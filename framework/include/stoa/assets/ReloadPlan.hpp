#pragma once
// What the asset cache knows when files change on disk, and the question it
// asks (lab 11's assetsToReload()): which assets should load again now?
//
// Editors save in bursts (write a temporary file, rename it, touch it again),
// so the cache waits until a file has been quiet for a short while (the
// debounce) before it reloads, and reloads each asset once however many of
// its files changed. An asset's files are the file it was loaded from and
// every file that file pulled in (a shader's #includes, a model's material
// and textures, a crowd world's agent file).
//
//   std::vector<std::string> due = assetsToReload(changes, assets, now, 0.2);

#include <functional>
#include <string>
#include <vector>

namespace stoa {

/// One change to a file, as the file watcher saw it.
struct FileChange {
    std::string file;     // absolute, lexically normal path
    double seconds = 0.0; // when it changed, on the cache's clock
};

/// One asset of the cache and the files it was built from.
struct AssetFiles {
    std::string name;               // the asset's name in the cache, e.g. "textures/marble.png"
    std::vector<std::string> files; // absolute, lexically normal paths
    double loadedAt = 0.0;          // when it was last loaded, on the cache's clock
};

/// The question as the cache asks it: given the changes it has seen, its
/// assets, the time now and the debounce (seconds), the names of the assets to
/// load again, in the order of `assets`, each once. Lab 11's assetsToReload()
/// fits it; a program hands it over with AssetCache::setReloadDispatch(), as
/// the framework cannot call lab code itself.
using ReloadDispatch = std::function<std::vector<std::string>(
    const std::vector<FileChange>& changes, const std::vector<AssetFiles>& assets, double now, double debounceSeconds)>;

} // namespace stoa
