#pragma once
// Keeps the reference images out of a lab program's reach. Before grading, the
// guard records every file in the folders that hold the references (size,
// modification time, a hash, and the bytes themselves) and decodes the
// references once. After each case it checks those files: one that changed or
// went away is restored from memory, one that appeared is removed, and the case
// that made the change is blamed. Cases run several at a time, so a change found
// when one ends may be another's: runAndVerify() runs a case again with no other
// case beside it whenever a change was found while it ran, and blames only what
// it changes alone. The comparison reads the decoded copy held here, so a
// reference changed on disk, even by a case running at the same moment, never
// changes a grade.

#include <stoa/image/Image.hpp>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <shared_mutex>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace stoa::grader {

class ReferenceGuard {
public:
    /// Records `references` (files that may be missing) and every regular file in
    /// their folders. Never throws for a file it cannot read: that file is then
    /// only watched for appearing. `workFolders` are the grader's own (the cases'
    /// work folders, made later): where one lies inside a guarded folder, the
    /// entry that leads to it is not "a file that appeared" and stays.
    explicit ReferenceGuard(const std::vector<std::filesystem::path>& references,
                            const std::vector<std::filesystem::path>& workFolders = {});

    /// The reference decoded at construction; nullptr when it did not exist or did
    /// not decode (then decodeError() says why).
    const Image* image(const std::filesystem::path& reference) const;
    /// Why `reference` did not decode ("" when it did or did not exist).
    std::string decodeError(const std::filesystem::path& reference) const;

    /// Compares every guarded file with its record, restores what changed and
    /// removes what appeared. Returns the paths that had changed, appeared or
    /// gone (empty when none). Safe to call from several threads at once.
    std::vector<std::filesystem::path> verifyAndRestore();

    /// Runs `runCase` (one case's lab program) beside the other cases, then
    /// verifyAndRestore(). When a change was found while it ran, by its own check
    /// or by that of a case beside it, which of them made it is unknown: it waits
    /// for the others to end and runs `runCase` again alone. Returns the paths the
    /// case changed (empty when none), so a case is blamed only for its own
    /// changes; `runCase` has then run once, or twice and the last run stands.
    std::vector<std::filesystem::path> runAndVerify(const std::function<void()>& runCase);

    /// The number of files it guards.
    std::size_t size() const { return m_files.size(); }

private:
    struct Record {
        bool existed = false;
        std::uintmax_t size = 0;
        std::filesystem::file_time_type modified;
        std::uint64_t hash = 0;
        std::string bytes;
    };
    struct Decoded {
        std::optional<Image> image;
        std::string error;
    };

    void record(const std::filesystem::path& file);
    bool unchanged(const std::filesystem::path& file, const Record& record) const;

    std::map<std::filesystem::path, Record> m_files;
    std::vector<std::filesystem::path> m_folders;
    std::set<std::filesystem::path> m_presentAtStart;   // every entry of the guarded folders at construction
    std::set<std::filesystem::path> m_graderEntries;    // entries of the guarded folders on the way to a work folder
    std::map<std::filesystem::path, Decoded> m_decoded;
    std::mutex m_mutex;
    std::shared_mutex m_turns;                  // shared: a case beside others; unique: a case alone
    std::atomic<std::uint64_t> m_changesFound{0};   // checks that found a change
    std::atomic<std::uint64_t> m_casesStarted{0};
    std::atomic<int> m_casesRunning{0};
};

/// FNV-1a, 64 bits: enough to notice a changed file (not a defence against collisions;
/// the bytes are compared too).
std::uint64_t contentHash(const std::string& bytes);

} // namespace stoa::grader
