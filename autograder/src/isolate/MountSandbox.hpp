#pragma once
// The fallback for FileSandbox where Landlock is missing but the child has a
// mount namespace of its own (in its own user namespace): a FileAccess turned
// into mounts, made in the child just before exec.
//
//   - every writable path is bound onto itself first, so that it stays writable;
//   - every excluded subtree is covered by an empty read-only tmpfs, with the
//     granted paths below it (the program's build, its case folder) bound back;
//   - every other mount is remounted read-only.
//
// So the program can write only its case folder and the shader cache, and sees
// nothing of the excluded trees (solutions/, the work folder, and in a class
// batch the submissions and the grades). Unlike Landlock it can still read what
// lies outside the excluded trees (the rest of the user's files).

#include "FileSandbox.hpp"

#include <string>
#include <vector>

namespace stoa::grader {

/// The mounts for a FileAccess, prepared before fork (the child may not allocate).
class MountSandbox {
public:
    MountSandbox() = default;
    /// Plans the mounts for `access` from this process's mount table. Empty
    /// (valid() false) for an unconfined access.
    explicit MountSandbox(const FileAccess& access);

    bool valid() const { return m_valid; }

    /// In the child, in its own mount namespace, before exec. Async-signal-safe.
    /// Returns 0, or the errno of the first mount that failed.
    int enter() const;

private:
    struct Bind {
        std::string source;       // a granted path below a cover
        std::string target;       // the same path: where it is bound back
        bool writable = false;
        bool isFolder = true;
        unsigned long flags = 0;  // its mount's flags to keep when made read-only
    };
    struct Cover {
        std::string path;                   // an excluded subtree
        std::vector<std::string> folders;   // folders to make in its tmpfs, parents first
        std::vector<std::string> files;     // empty files to make there (a file bound back)
        std::vector<Bind> binds;
    };
    struct ReadOnly {
        std::string path;         // a mount point of the grader's mount table
        unsigned long flags = 0;  // its flags to keep (nosuid, nodev, noexec, atime)
    };
    bool m_valid = false;
    std::vector<std::string> m_writable;
    std::vector<Cover> m_covers;
    std::vector<ReadOnly> m_readOnly;
    mutable std::vector<int> m_descriptors;   // one per Bind, filled in the child (sized before fork)
};

} // namespace stoa::grader
