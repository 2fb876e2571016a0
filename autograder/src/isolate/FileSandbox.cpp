#include "FileSandbox.hpp"

#include "ProcessContainment.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <mutex>

#include <fcntl.h>
#include <linux/landlock.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

// The rights of Landlock ABIs newer than the kernel headers this may be built with.
#ifndef LANDLOCK_ACCESS_FS_REFER
#define LANDLOCK_ACCESS_FS_REFER (1ULL << 13)        // ABI 2
#endif
#ifndef LANDLOCK_ACCESS_FS_TRUNCATE
#define LANDLOCK_ACCESS_FS_TRUNCATE (1ULL << 14)     // ABI 3
#endif
#ifndef LANDLOCK_ACCESS_FS_IOCTL_DEV
#define LANDLOCK_ACCESS_FS_IOCTL_DEV (1ULL << 15)    // ABI 5
#endif
#ifndef LANDLOCK_CREATE_RULESET_VERSION
#define LANDLOCK_CREATE_RULESET_VERSION (1U << 0)
#endif

namespace stoa::grader {

namespace {

using Access = std::uint64_t;

constexpr Access kRead = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
constexpr Access kWrite = kRead | LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_REMOVE_DIR |
                          LANDLOCK_ACCESS_FS_REMOVE_FILE | LANDLOCK_ACCESS_FS_MAKE_DIR |
                          LANDLOCK_ACCESS_FS_MAKE_REG | LANDLOCK_ACCESS_FS_MAKE_SOCK | LANDLOCK_ACCESS_FS_MAKE_FIFO |
                          LANDLOCK_ACCESS_FS_MAKE_SYM | LANDLOCK_ACCESS_FS_REFER | LANDLOCK_ACCESS_FS_TRUNCATE;
constexpr Access kDevice = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR |
                           LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_IOCTL_DEV;
// The rights a rule on a file (not a folder) may carry.
constexpr Access kFileRights = LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE |
                               LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_TRUNCATE |
                               LANDLOCK_ACCESS_FS_IOCTL_DEV;

// Every right the kernel's ABI knows: what the ruleset handles (denies unless granted).
Access handledRights(int abi) {
    Access rights = (LANDLOCK_ACCESS_FS_MAKE_SYM << 1) - 1;   // ABI 1: bits 0-12
    if (abi >= 2) rights |= LANDLOCK_ACCESS_FS_REFER;
    if (abi >= 3) rights |= LANDLOCK_ACCESS_FS_TRUNCATE;
    if (abi >= 5) rights |= LANDLOCK_ACCESS_FS_IOCTL_DEV;
    return rights;
}

void walk(const std::filesystem::path& root, const std::vector<std::filesystem::path>& excluded,
          std::vector<std::filesystem::path>& out) {
    bool holdsExcluded = false;
    for (const std::filesystem::path& path : excluded) {
        if (pathWithin(root, path)) return;   // (only reached below the top: the caller drops the ancestors)
        if (pathWithin(path, root)) holdsExcluded = true;
    }
    if (!holdsExcluded) {
        out.push_back(root);
        return;
    }
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(root, error)) walk(entry.path(), excluded, out);
}

// Grants `rights` on `path` (a folder: everything below it too) in `ruleset`.
// A path that does not exist, or that this user cannot reach, is skipped (left
// denied); returns an error text otherwise.
std::string addRule(int ruleset, const std::filesystem::path& path, Access rights, Access handled) {
    int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
    if (fd < 0)
        return errno == ENOENT || errno == ENOTDIR || errno == EACCES ? "" : path.string() + ": " + std::strerror(errno);
    struct stat info {};
    if (fstat(fd, &info) == 0 && !S_ISDIR(info.st_mode)) rights &= kFileRights;
    landlock_path_beneath_attr rule{};
    rule.allowed_access = rights & handled;
    rule.parent_fd = fd;
    long added = syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
    int saved = errno;
    close(fd);
    if (added != 0 && rule.allowed_access != 0) return path.string() + ": landlock_add_rule: " + std::strerror(saved);
    return "";
}

} // namespace

std::filesystem::path normalPath(const std::filesystem::path& path) {
    std::error_code error;
    std::filesystem::path absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(path), error);
    return error ? std::filesystem::absolute(path).lexically_normal() : absolute;
}

bool pathWithin(const std::filesystem::path& inner, const std::filesystem::path& outer) {
    auto mismatch = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
    return mismatch.first == outer.end();
}

FileAccess systemFileAccess() {
    FileAccess access;
    access.confine = true;
    for (const char* folder : {"/usr", "/lib", "/lib32", "/lib64", "/libx32", "/bin", "/sbin", "/etc", "/opt",
                               "/proc", "/sys"})
        access.readable.emplace_back(folder);
    access.devices.emplace_back("/dev");
    return access;
}

std::vector<std::filesystem::path> treeWithout(const std::filesystem::path& root,
                                               const std::vector<std::filesystem::path>& excluded) {
    std::filesystem::path top = normalPath(root);
    std::vector<std::filesystem::path> below;
    for (const std::filesystem::path& path : excluded) {
        std::filesystem::path cut = normalPath(path);
        if (!pathWithin(top, cut)) below.push_back(cut);
    }
    std::vector<std::filesystem::path> out;
    walk(top, below, out);
    return out;
}

namespace {
int g_abi = 0;   // set once by landlockAbi(), before any sandbox is made; read in the child
} // namespace

int landlockAbi() {
    static std::once_flag probed;
    std::call_once(probed, [] {
        long version = syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
        g_abi = version > 0 ? static_cast<int>(version) : 0;
    });
    return g_abi;
}

std::string fileConfinementNote() {
    if (filesCanBeConfined()) return "";
    if (pidNamespaceFlags() & CLONE_NEWNS)
        return "note: Landlock (Linux 5.13 or newer) is not available: the lab programs' files are confined with a "
               "mount namespace instead (they write only their case folder and do not see solutions/, the "
               "submissions or the grades, but can read this user's other files)";
    return "note: this system cannot confine the lab programs' files (neither Landlock, Linux 5.13 or newer, nor a "
           "mount namespace is available): they can read and write what this user can";
}

FileSandbox::FileSandbox(const FileAccess& access) {
    const int abi = landlockAbi();
    if (!access.confine || access.preferMounts || abi == 0) return;
    const Access handled = handledRights(abi);
    landlock_ruleset_attr attributes{};
    attributes.handled_access_fs = handled;
    long ruleset = syscall(SYS_landlock_create_ruleset, &attributes, sizeof attributes, 0);
    if (ruleset < 0) {
        m_error = std::string("landlock_create_ruleset: ") + std::strerror(errno);
        return;
    }
    m_ruleset = static_cast<int>(ruleset);
    fcntl(m_ruleset, F_SETFD, FD_CLOEXEC);
    std::vector<std::filesystem::path> excluded;
    for (const std::filesystem::path& path : access.excluded) excluded.push_back(normalPath(path));
    auto grant = [&](const std::filesystem::path& path, Access rights) {
        if (!m_error.empty()) return;
        m_error = addRule(m_ruleset, path, rights, handled);
    };
    for (const std::filesystem::path& tree : access.readable)
        for (const std::filesystem::path& path : treeWithout(tree, excluded)) grant(path, kRead);
    for (const std::filesystem::path& path : access.writable) grant(normalPath(path), kWrite);
    for (const std::filesystem::path& path : access.devices) grant(normalPath(path), kDevice);
    if (!m_error.empty()) {
        close(m_ruleset);
        m_ruleset = -1;
    }
}

FileSandbox::~FileSandbox() {
    if (m_ruleset >= 0) close(m_ruleset);
}

FileSandbox::FileSandbox(FileSandbox&& other) noexcept : m_ruleset(other.m_ruleset), m_error(std::move(other.m_error)) {
    other.m_ruleset = -1;
}

FileSandbox& FileSandbox::operator=(FileSandbox&& other) noexcept {
    if (this != &other) {
        if (m_ruleset >= 0) close(m_ruleset);
        m_ruleset = other.m_ruleset;
        m_error = std::move(other.m_error);
        other.m_ruleset = -1;
    }
    return *this;
}

int enterFileSandbox(int rulesetDescriptor) {
    int proc = open("/proc", O_PATH | O_CLOEXEC);
    if (proc >= 0) {
        landlock_path_beneath_attr rule{};
        rule.allowed_access = kRead & handledRights(g_abi);
        rule.parent_fd = proc;
        syscall(SYS_landlock_add_rule, rulesetDescriptor, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
        close(proc);
    }
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return errno;
    if (syscall(SYS_landlock_restrict_self, rulesetDescriptor, 0) != 0) return errno;
    close(rulesetDescriptor);
    return 0;
}

} // namespace stoa::grader
