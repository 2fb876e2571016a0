// Lab 11, part 4: which assets to reload. Read docs/labs/11_editor.md,
// "Hot reload", first.

#include "lab11.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <algorithm>

namespace stoa {

std::vector<std::string> assetsToReload(const std::vector<FileChange>& changes, const std::vector<AssetFiles>& assets,
                                        double now, double debounceSeconds) {
    // TODO(lab11): for each asset, look at the changes to its files: is one
    // of them newer than loadedAt, and is the latest of them at least
    // debounceSeconds old? (docs: "Waiting for quiet")
    (void)changes;
    (void)assets;
    (void)now;
    (void)debounceSeconds;
    throw NotImplemented("assetsToReload()");
}

} // namespace stoa
