#pragma once
// Keeps the reference images out of a lab program's reach. Before grading, the
// guard records every file in the folders that hold the references (size,
// modification time, a hash, and the bytes themselves) and decodes the
// references once. After each case it checks those files: one that changed or
// went away is restored from memory, one that appeared is removed, and the case
// that just ran is blamed. The comparison reads the decoded copy held here, so a
// reference changed on disk, even by a case running at the same moment, never
// changes a grade.

#include <stoa/image/Image.hpp>

#include <cstdint>
#include <filesystem>
#include <set>
#include <map>
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
};

/// FNV-1a, 64 bits: enough to notice a changed file (not a defence against collisions;
/// the bytes are compared too).
std::uint64_t contentHash(const std::string& bytes);

} // namespace stoa::grader
