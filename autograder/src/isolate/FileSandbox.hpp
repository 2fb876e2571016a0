#pragma once
// What files a child may touch. A lab program of one student must not read or
// write another's work, the submissions, the grades or solutions/, whatever it
// learns from /proc: the grader hands it a FileAccess (the trees it may read,
// the folder it may write) and the kernel enforces it with Landlock (Linux 5.13
// or newer, no privileges needed), set in the child just before exec, after
// which neither the program nor anything it starts can widen it.
//
// Where Landlock is missing (an older kernel, a container that filters its
// system calls), a mount namespace stands in where the child gets one
// (MountSandbox.hpp: it hides the excluded trees and makes all but the writable
// paths read-only); where neither is there, the child runs with the grader's own
// file access. The grader says so once (fileConfinementNote()).

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

/// The files a child may touch. `confine` false (the default): whatever the
/// grader may. Paths that do not exist are skipped; a file may stand for a tree.
struct FileAccess {
    bool confine = false;
    std::vector<std::filesystem::path> readable;   // read, list, execute
    std::vector<std::filesystem::path> writable;   // also create, write, truncate, rename, remove
    std::vector<std::filesystem::path> devices;    // device files: open for reading and writing, ioctl
    /// Subtrees carved out of the readable trees that contain them (the grades
    /// folder inside a build folder); a readable or writable path inside one
    /// stays granted.
    std::vector<std::filesystem::path> excluded;
    /// The mount namespace fallback (MountSandbox.hpp) even where Landlock is
    /// there: for the tests of the fallback.
    bool preferMounts = false;
};

/// Confined access to what every program needs: the system's folders (/usr,
/// /lib*, /bin, /sbin, /etc, /opt, /proc, /sys) to read, /dev's device files
/// (the GL drivers' /dev/dri, /dev/null) to open.
FileAccess systemFileAccess();

/// `path` absolute, with symbolic links resolved as far as it exists.
std::filesystem::path normalPath(const std::filesystem::path& path);

/// True when `inner` is `outer` or lies below it (both normalPath()s).
bool pathWithin(const std::filesystem::path& inner, const std::filesystem::path& outer);

/// The paths to grant for `root` with the `excluded` subtrees below it carved
/// out: {root} when none lies below it, else its entries, recursively, without
/// the excluded ones. An excluded path that contains `root` does not remove it.
std::vector<std::filesystem::path> treeWithout(const std::filesystem::path& root,
                                               const std::vector<std::filesystem::path>& excluded);

/// The Landlock ABI version this kernel offers (0: none). Probed once.
int landlockAbi();

/// True when FileAccess is enforced on this system.
inline bool filesCanBeConfined() { return landlockAbi() > 0; }

/// One line for a report when files cannot be confined with Landlock here
/// (saying whether the mount namespace fallback, MountSandbox.hpp, stands in),
/// else "".
std::string fileConfinementNote();

/// A Landlock ruleset made from a FileAccess before fork, for the child to enter.
/// Move-only; closes its descriptor.
class FileSandbox {
public:
    FileSandbox() = default;
    /// Builds the ruleset. An unconfined `access`, or a system without Landlock,
    /// gives an empty sandbox (valid() false, error() empty). A failure to build
    /// it gives valid() false and error() saying why.
    explicit FileSandbox(const FileAccess& access);
    ~FileSandbox();
    FileSandbox(FileSandbox&& other) noexcept;
    FileSandbox& operator=(FileSandbox&& other) noexcept;
    FileSandbox(const FileSandbox&) = delete;
    FileSandbox& operator=(const FileSandbox&) = delete;

    bool valid() const { return m_ruleset >= 0; }
    int descriptor() const { return m_ruleset; }
    const std::string& error() const { return m_error; }

private:
    int m_ruleset = -1;
    std::string m_error;
};

/// In the child, right before exec: read access to the /proc it sees now (a
/// PID namespace's own /proc is another mount than the one the ruleset was made
/// with), no new privileges, then the ruleset. Async-signal-safe. Returns 0, or
/// the errno of the step that failed.
int enterFileSandbox(int rulesetDescriptor);

} // namespace stoa::grader
