#include "ReferenceGuard.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <set>

namespace stoa::grader {

namespace {

namespace fs = std::filesystem;

bool readFile(const fs::path& path, std::string& bytes) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return false;
    bytes.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    return !file.bad();
}

bool writeFile(const fs::path& path, const std::string& bytes) {
    std::error_code ignored;
    fs::create_directories(path.parent_path(), ignored);
    // A hostile program may have left a read-only file or a folder in its place.
    fs::remove_all(path, ignored);
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return static_cast<bool>(file);
}

fs::path normalized(const fs::path& path) {
    std::error_code ignored;
    fs::path absolute = fs::absolute(path, ignored);
    return absolute.lexically_normal();
}

} // namespace

std::uint64_t contentHash(const std::string& bytes) {
    std::uint64_t hash = 1469598103934665603ull;
    for (unsigned char c : bytes) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return hash;
}

ReferenceGuard::ReferenceGuard(const std::vector<fs::path>& references, const std::vector<fs::path>& workFolders) {
    std::set<fs::path> folders;
    for (const fs::path& reference : references) {
        fs::path file = normalized(reference);
        folders.insert(file.parent_path());
        record(file);
        Decoded decoded;
        const Record& recorded = m_files[file];
        if (recorded.existed) {
            try {
                decoded.image = Image::load(file);
            } catch (const InputError& error) {
                decoded.error = error.message();
            }
        }
        m_decoded[file] = std::move(decoded);
    }
    for (const fs::path& folder : folders) {
        m_folders.push_back(folder);
        std::error_code error;
        for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
            m_presentAtStart.insert(it->path());   // folders too: the mistake gallery lives in one
            if (it->is_regular_file(error) && !m_files.count(it->path())) record(it->path());
        }
        // A work folder below a guarded folder (a test's temporary folder holding
        // both) is created, and filled, while other cases run.
        for (const fs::path& work : workFolders) {
            const fs::path inside = normalized(work).lexically_relative(folder);
            if (!inside.empty() && *inside.begin() != ".." && *inside.begin() != ".")
                m_graderEntries.insert(folder / *inside.begin());
        }
    }
}

void ReferenceGuard::record(const fs::path& file) {
    Record entry;
    std::error_code error;
    if (fs::is_regular_file(file, error) && readFile(file, entry.bytes)) {
        entry.existed = true;
        entry.size = entry.bytes.size();
        entry.modified = fs::last_write_time(file, error);
        entry.hash = contentHash(entry.bytes);
    }
    m_files[file] = std::move(entry);
}

bool ReferenceGuard::unchanged(const fs::path& file, const Record& entry) const {
    std::error_code error;
    bool exists = fs::exists(fs::symlink_status(file, error));
    if (!entry.existed) return !exists;
    if (!exists || fs::is_symlink(fs::symlink_status(file, error)) || !fs::is_regular_file(file, error)) return false;
    if (fs::file_size(file, error) != entry.size || fs::last_write_time(file, error) != entry.modified) return false;
    std::string bytes;
    return readFile(file, bytes) && contentHash(bytes) == entry.hash && bytes == entry.bytes;
}

const Image* ReferenceGuard::image(const fs::path& reference) const {
    auto found = m_decoded.find(normalized(reference));
    return found != m_decoded.end() && found->second.image ? &*found->second.image : nullptr;
}

std::string ReferenceGuard::decodeError(const fs::path& reference) const {
    auto found = m_decoded.find(normalized(reference));
    return found != m_decoded.end() ? found->second.error : "";
}

std::vector<fs::path> ReferenceGuard::verifyAndRestore() {
    std::lock_guard<std::mutex> lock(m_mutex);
    std::vector<fs::path> changed;
    for (auto& [file, entry] : m_files) {
        if (unchanged(file, entry)) continue;
        changed.push_back(file);
        std::error_code error;
        if (!entry.existed) {
            fs::remove_all(file, error);
        } else if (writeFile(file, entry.bytes)) {
            entry.modified = fs::last_write_time(file, error); // the restored copy's time
        }
    }
    // Files that appeared in the guarded folders go too.
    for (const fs::path& folder : m_folders) {
        std::error_code error;
        std::vector<fs::path> added;
        for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
            if (!m_files.count(it->path()) && !m_presentAtStart.count(it->path()) && !m_graderEntries.count(it->path()))
                added.push_back(it->path());
        for (const fs::path& path : added) {
            fs::remove_all(path, error);
            changed.push_back(path);
        }
    }
    std::sort(changed.begin(), changed.end());
    if (!changed.empty()) ++m_changesFound;
    return changed;
}

std::vector<fs::path> ReferenceGuard::runAndVerify(const std::function<void()>& runCase) {
    {
        std::shared_lock<std::shared_mutex> beside(m_turns);
        const std::uint64_t changesBefore = m_changesFound;
        const std::uint64_t startedBefore = m_casesStarted++;
        const bool aloneAtStart = ++m_casesRunning == 1;
        runCase();
        std::vector<fs::path> changed = verifyAndRestore();
        const bool alone = aloneAtStart && m_casesStarted == startedBefore + 1;
        --m_casesRunning;
        if (m_changesFound == changesBefore || alone) return changed;
    }
    std::unique_lock<std::shared_mutex> onlyThisCase(m_turns);
    ++m_casesStarted;
    runCase();
    return verifyAndRestore();
}

} // namespace stoa::grader
