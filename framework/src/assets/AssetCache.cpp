#include <stoa/assets/AssetCache.hpp>

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <exception>
#include <set>
#include <unordered_set>

namespace fs = std::filesystem;

namespace stoa {

AssetCache::AssetCache(fs::path root, AssetCacheOptions options)
    : m_root(std::move(root)), m_options(options), m_watcher(options.watcher) {}

fs::path AssetCache::pathOf(const std::string& name) const { return (m_root / name).lexically_normal(); }

void AssetCache::add(Entry entry, const std::vector<fs::path>& files, const std::vector<std::string>& warnings) {
    // An asset loaded between two updates counts as loaded at the last one. A
    // change it already read that the watcher only reports at the next update
    // makes one needless reload, never a missed one.
    entry.files.loadedAt = m_now;
    setFiles(entry, files);
    for (const std::string& warning : warnings) m_log.push_back(entry.files.name + ": " + warning);
    m_index.emplace(entry.files.name, m_entries.size());
    m_entries.push_back(std::move(entry));
}

void AssetCache::setFiles(Entry& entry, const std::vector<fs::path>& files) {
    entry.files.files.clear();
    for (const fs::path& file : files) {
        const std::string normal = FileWatcher::normalPath(file);
        if (std::find(entry.files.files.begin(), entry.files.files.end(), normal) != entry.files.files.end()) continue;
        entry.files.files.push_back(normal);
        m_watcher.watch(normal);
    }
}

void AssetCache::update(double now) {
    m_now = now;
    for (FileChange& change : m_watcher.poll(now)) m_changes.push_back(std::move(change));
    for (std::string& line : m_watcher.takeLog()) m_log.push_back(std::move(line));
    if (m_changes.empty()) return;

    const std::vector<AssetFiles> plan = assets();
    const std::vector<std::string> due = m_dispatch ? m_dispatch(m_changes, plan, now, m_options.debounceSeconds)
                                                    : changedSinceLoaded(m_changes, plan);
    std::set<std::string> done;
    for (const std::string& name : due) {
        const auto found = m_index.find(name);
        if (found == m_index.end()) {
            m_log.push_back("the reload dispatch named '" + name + "', which is not in the cache; ignored");
            continue;
        }
        if (!done.insert(name).second) continue; // named twice: loaded once
        reload(m_entries[found->second], now);
    }
    pruneChanges();
}

void AssetCache::reload(Entry& entry, double now) {
    const std::string& name = entry.files.name;
    // Failed or not, the asset counts as loaded now: a failure is tried again
    // at the next change of one of its files, not at every frame.
    entry.files.loadedAt = now;
    try {
        auto [files, warnings] = entry.reload();
        setFiles(entry, files);
        entry.error.clear();
        for (const std::string& warning : warnings) m_log.push_back(name + ": " + warning);
        m_log.push_back("reloaded " + name);
    } catch (const InputError& error) {
        entry.error = error.what();
        // The file the error names is worth watching too (a new #include
        // that does not exist yet, once created, is a reason to try again).
        std::error_code ignored;
        if (!error.file().empty() && fs::is_regular_file(error.file(), ignored)) {
            std::vector<fs::path> files(entry.files.files.begin(), entry.files.files.end());
            files.push_back(error.file());
            setFiles(entry, files);
        }
        m_log.push_back("cannot reload " + name + ", keeping the last good version: " + entry.error);
    } catch (const std::exception& error) {
        entry.error = error.what();
        m_log.push_back("cannot reload " + name + ", keeping the last good version: " + entry.error);
    }
}

void AssetCache::pruneChanges() {
    // A change matters while some asset built from its file was loaded before
    // it. Keeping those only keeps the list short; the dispatch decides the same.
    std::unordered_map<std::string, double> oldestLoad; // file -> the earliest loadedAt of the assets that use it
    for (const Entry& entry : m_entries) {
        for (const std::string& file : entry.files.files) {
            const auto [place, added] = oldestLoad.emplace(file, entry.files.loadedAt);
            if (!added) place->second = std::min(place->second, entry.files.loadedAt);
        }
    }
    const auto stale = [&](const FileChange& change) {
        const auto found = oldestLoad.find(change.file);
        return found == oldestLoad.end() || change.seconds <= found->second;
    };
    m_changes.erase(std::remove_if(m_changes.begin(), m_changes.end(), stale), m_changes.end());
}

std::vector<std::string> AssetCache::changedSinceLoaded(const std::vector<FileChange>& changes,
                                                        const std::vector<AssetFiles>& assets) {
    std::vector<std::string> due;
    for (const AssetFiles& asset : assets) {
        const std::unordered_set<std::string> files(asset.files.begin(), asset.files.end());
        const bool changed = std::any_of(changes.begin(), changes.end(), [&](const FileChange& change) {
            return change.seconds > asset.loadedAt && files.count(change.file);
        });
        if (changed) due.push_back(asset.name);
    }
    return due;
}

std::vector<std::string> AssetCache::takeLog() {
    for (std::string& line : m_watcher.takeLog()) m_log.push_back(std::move(line));
    return std::exchange(m_log, {});
}

std::string AssetCache::errorOf(const std::string& name) const {
    const auto found = m_index.find(name);
    return found == m_index.end() ? std::string() : m_entries[found->second].error;
}

std::vector<AssetFiles> AssetCache::assets() const {
    std::vector<AssetFiles> result;
    result.reserve(m_entries.size());
    for (const Entry& entry : m_entries) result.push_back(entry.files);
    return result;
}

} // namespace stoa
