#include "SafeSave.hpp"

#include <stoa/core/InputError.hpp>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <optional>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stoa {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxLinks = 40;   // links followed before a chain counts as a loop (Linux's own limit)

std::string describeWriteError(int error, const fs::path& folder) {
    switch (error) {
    case ENOENT:
    case ENOTDIR: return "the folder " + folder.string() + " does not exist";
    case EACCES:
    case EPERM: return "permission denied: cannot write in the folder " + folder.string();
    case ENOSPC: return "the disk is full";
    case EDQUOT: return "the disk quota is used up";
    case EROFS: return "the folder " + folder.string() + " is on a read-only file system";
    case EISDIR: return "this is a folder, not a file";
    case ELOOP: return "the path to the folder " + folder.string() + " holds a symbolic link loop";
    default: return std::strerror(error);
    }
}

/// Writes all of `text` to `fd`, then flushes it to the disk; errno on failure.
bool writeAll(int fd, const std::string& text) {
    std::size_t written = 0;
    while (written < text.size()) {
        const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        written += static_cast<std::size_t>(n);
    }
    return ::fsync(fd) == 0;
}

/// `file` with the symbolic links at its end followed, each relative to the
/// link's own folder; nullopt for a loop (more than kMaxLinks links). The
/// result may not exist (a link to a file not yet written).
std::optional<fs::path> followLinks(const fs::path& file) {
    fs::path path = file;
    for (int hop = 0; hop <= kMaxLinks; ++hop) {
        struct stat info {};
        if (::lstat(path.c_str(), &info) != 0 || !S_ISLNK(info.st_mode)) return path;
        std::error_code error;
        const fs::path target = fs::read_symlink(path, error);
        if (error) return path;
        path = target.is_absolute() ? target : path.parent_path() / target;
    }
    return std::nullopt;
}

/// Why a save must not replace what is at `target` (`subject` names it in
/// the message); empty for a writable regular file or nothing at all. Read
/// with lstat: nothing is opened, so a FIFO cannot block.
std::string whyNotReplace(const fs::path& target, const std::string& subject) {
    struct stat info {};
    if (::lstat(target.c_str(), &info) != 0) return "";   // nothing there; a missing folder is reported when writing
    const char* kind = nullptr;
    switch (info.st_mode & S_IFMT) {
    case S_IFREG:
        // The write bits, not access(): root may write anything, but a file
        // someone made read-only is still not to be replaced.
        if ((info.st_mode & 0222) != 0) return "";
        return subject + " is read-only (make it writable, or save under another name)";
    case S_IFDIR: kind = "a folder"; break;
    case S_IFIFO: kind = "a FIFO (a named pipe)"; break;
    case S_IFCHR: kind = "a character device"; break;
    case S_IFBLK: kind = "a block device"; break;
    case S_IFSOCK: kind = "a socket"; break;
    default: kind = "something other than a file"; break;
    }
    return subject + " is " + kind + ", not a regular file; a save replaces only a regular file";
}

/// The PID in `entry` when it reads `prefix` PID "-" N (N a counter); 0 when not.
pid_t savingPid(const std::string& entry, const std::string& prefix) {
    if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return 0;
    const char* const last = entry.data() + entry.size();
    const char* const first = entry.data() + prefix.size();
    pid_t pid = 0;
    const auto [dash, pidError] = std::from_chars(first, last, pid);
    if (pidError != std::errc() || pid <= 0 || dash == last || *dash != '-') return 0;
    unsigned long long counter = 0;
    const auto [end, counterError] = std::from_chars(dash + 1, last, counter);
    if (counterError != std::errc() || end != last) return 0;
    return pid;
}

/// Removes `.NAME.saving-PID-N` in `folder` when process PID no longer runs.
void removeStaleTemporaries(const fs::path& folder, const std::string& name) {
    const std::string prefix = "." + name + ".saving-";
    DIR* const dir = ::opendir(folder.c_str());
    if (!dir) return;
    while (const dirent* entry = ::readdir(dir)) {
        const pid_t pid = savingPid(entry->d_name, prefix);
        if (pid == 0 || pid == ::getpid()) continue;
        // Signal 0 sends nothing, it only asks: ESRCH is "no such process";
        // EPERM is a running process of another user, whose file stays.
        if (::kill(pid, 0) == 0 || errno != ESRCH) continue;
        struct stat info {};
        if (::fstatat(::dirfd(dir), entry->d_name, &info, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(info.st_mode))
            (void)::unlinkat(::dirfd(dir), entry->d_name, 0);
    }
    ::closedir(dir);
}

/// Creates a new temporary file for `target` in `folder` and returns its
/// descriptor; -1 with errno set when none could be made.
int openTemporary(const fs::path& folder, const fs::path& target, fs::path& temporary) {
    static std::atomic<unsigned> counter{0};
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        temporary = folder / ("." + target.filename().string() + ".saving-" + std::to_string(::getpid()) + "-" +
                              std::to_string(counter++));
        fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    return fd;
}

/// Flushes the folder's entries to the disk, so that a rename in it survives a power cut.
void syncFolder(const fs::path& folder) {
    const int folderFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folderFd < 0) return;
    (void)::fsync(folderFd);
    ::close(folderFd);
}

} // namespace

void saveFileSafely(const fs::path& file, const std::string& text, const std::string& what) {
    const std::string name = file.string();
    const auto refuse = [&](const std::string& why) { throw InputError(name, 0, "cannot save " + what + ": " + why); };
    if (name.empty()) refuse("no file was named (the path is empty)");
    // Through a symbolic link into the file it names: the link stays a link.
    const std::optional<fs::path> followed = followLinks(file);
    if (!followed) {
        refuse("it is a symbolic link loop (following the links never reaches a file); remove a link or save under "
               "another name");
    }
    const fs::path& target = *followed;
    const std::string subject = target == file ? "it" : "the link's target " + target.string();
    if (const std::string why = whyNotReplace(target, subject); !why.empty()) refuse(why);

    // Same folder as the target, so same file system: the rename is one step.
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    removeStaleTemporaries(folder, target.filename().string());
    struct stat existing {};
    const bool exists = ::stat(target.c_str(), &existing) == 0;
    fs::path temporary;
    const int fd = openTemporary(folder, target, temporary);
    if (fd < 0) refuse(describeWriteError(errno, folder));

    // A file saved over an existing one keeps its permissions.
    if (exists) (void)::fchmod(fd, existing.st_mode & 07777);
    const bool written = writeAll(fd, text);
    int error = written ? 0 : errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    // Checked again just before the rename: what was swapped in meanwhile is not replaced either.
    const std::string why = error == 0 ? whyNotReplace(target, subject) : std::string();
    if (error == 0 && why.empty() && ::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
    if (error != 0 || !why.empty()) {
        ::unlink(temporary.c_str());
        refuse(why.empty() ? describeWriteError(error, folder) : why);
    }
    syncFolder(folder);
}

void removeStaleSaves(const fs::path& file) {
    const std::optional<fs::path> target = followLinks(file);
    if (!target || target->filename().empty()) return;
    const fs::path folder = target->has_parent_path() ? target->parent_path() : fs::path(".");
    removeStaleTemporaries(folder, target->filename().string());
}

} // namespace stoa
