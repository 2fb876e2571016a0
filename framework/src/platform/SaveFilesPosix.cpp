// SaveFiles on POSIX: open(O_EXCL) and fsync() for the new file, rename() to
// replace, kill(pid, 0) to ask whether a process runs.
#include <stoa/platform/SaveFiles.hpp>

#ifndef _WIN32

#include <cerrno>
#include <climits>
#include <cstring>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stoa::platform {

namespace fs = std::filesystem;

namespace {

std::error_code lastError() { return {errno, std::generic_category()}; }

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

} // namespace

ProcessId currentProcessId() { return ::getpid(); }

bool processHasEnded(ProcessId pid) {
    if (pid <= 0 || pid > INT_MAX) return false; // not a pid_t: cannot be asked
    // Signal 0 sends nothing, it only asks: ESRCH is "no such process";
    // EPERM is a running process of another user.
    return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

std::error_code writeNewFile(const fs::path& path, const std::string& text, const fs::path& permissionsOf) {
    struct stat existing {};
    const bool exists = ::stat(permissionsOf.c_str(), &existing) == 0;
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return lastError();
    // A file saved over an existing one keeps its permissions.
    if (exists) (void)::fchmod(fd, existing.st_mode & 07777);
    std::error_code error;
    if (!writeAll(fd, text)) error = lastError();
    if (::close(fd) != 0 && !error) error = lastError();
    if (error) ::unlink(path.c_str());
    return error;
}

std::error_code replaceFile(const fs::path& from, const fs::path& to) {
    if (::rename(from.c_str(), to.c_str()) != 0) return lastError();
    return {};
}

void removeFile(const fs::path& file) { ::unlink(file.c_str()); }

void flushFolder(const fs::path& folder) {
    const int folderFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folderFd < 0) return;
    (void)::fsync(folderFd);
    ::close(folderFd);
}

void removeRegularFilesIf(const fs::path& folder, const std::function<bool(const std::string& name)>& isStale) {
    DIR* const dir = ::opendir(folder.c_str());
    if (!dir) return;
    while (const dirent* entry = ::readdir(dir)) {
        if (!isStale(entry->d_name)) continue;
        // Looked at and removed relative to the open folder: no path to swap meanwhile.
        struct stat info {};
        if (::fstatat(::dirfd(dir), entry->d_name, &info, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(info.st_mode))
            (void)::unlinkat(::dirfd(dir), entry->d_name, 0);
    }
    ::closedir(dir);
}

std::string describeWriteError(const std::error_code& error, const fs::path& folder) {
    switch (error.value()) {
    case ENOENT:
    case ENOTDIR: return "the folder " + folder.string() + " does not exist";
    case EACCES:
    case EPERM: return "permission denied: cannot write in the folder " + folder.string();
    case ENOSPC: return "the disk is full";
    case EDQUOT: return "the disk quota is used up";
    case EROFS: return "the folder " + folder.string() + " is on a read-only file system";
    case EISDIR: return "this is a folder, not a file";
    case ELOOP: return "the path to the folder " + folder.string() + " holds a symbolic link loop";
    default: return std::strerror(error.value());
    }
}

} // namespace stoa::platform

#endif
