// Lab 11, part 4: which assets to reload. Read docs/labs/11_editor.md,
// "Hot reload", first.

#include "lab11.hpp"

#include <algorithm>

namespace stoa {

std::vector<std::string> assetsToReload(const std::vector<FileChange>& changes, const std::vector<AssetFiles>& assets,
                                        double now, double debounceSeconds) {
    std::vector<std::string> due;
    for (const AssetFiles& asset : assets) {
        bool changedSinceLoad = false;
        double latest = -1e300;
        for (const FileChange& change : changes) {
            if (std::find(asset.files.begin(), asset.files.end(), change.file) == asset.files.end()) continue;
            latest = std::max(latest, change.seconds);
            if (change.seconds > asset.loadedAt) changedSinceLoad = true;
        }
        if (changedSinceLoad && latest <= now - debounceSeconds) due.push_back(asset.name);
    }
    return due;
}

} // namespace stoa
