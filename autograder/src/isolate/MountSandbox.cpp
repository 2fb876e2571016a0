#include "MountSandbox.hpp"

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace stoa::grader {

namespace {

// True when `inner` lies strictly below `outer`.
bool below(const std::filesystem::path& inner, const std::filesystem::path& outer) {
    return pathWithin(inner, outer) && inner != outer;
}

// The mount flags a bind remount must keep (in a user namespace the kernel
// refuses to clear the ones it locked), from statvfs's.
unsigned long keptFlags(const std::string& path) {
    struct statvfs info {};
    if (statvfs(path.c_str(), &info) != 0) return 0;
    unsigned long flags = 0;
    if (info.f_flag & ST_NOSUID) flags |= MS_NOSUID;
    if (info.f_flag & ST_NODEV) flags |= MS_NODEV;
    if (info.f_flag & ST_NOEXEC) flags |= MS_NOEXEC;
    if (info.f_flag & ST_NOATIME) flags |= MS_NOATIME;
    if (info.f_flag & ST_NODIRATIME) flags |= MS_NODIRATIME;
    if (info.f_flag & ST_RELATIME) flags |= MS_RELATIME;
    if (info.f_flag & ST_RDONLY) flags |= MS_RDONLY;
    return flags;
}

// "/a\040b" -> "/a b": mountinfo escapes spaces, tabs, newlines and backslashes.
std::string unescape(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\' && i + 3 < text.size()) {
            out += static_cast<char>(std::stoi(text.substr(i + 1, 3), nullptr, 8));
            i += 3;
        } else {
            out += text[i];
        }
    }
    return out;
}

std::vector<std::string> mountPoints() {
    std::vector<std::string> points;
    std::ifstream table("/proc/self/mountinfo");
    for (std::string line; std::getline(table, line);) {
        std::istringstream fields(line);
        std::string id, parent, device, root, point;
        if (fields >> id >> parent >> device >> root >> point) points.push_back(unescape(point));
    }
    return points;
}

bool isPseudo(const std::string& path) {
    for (const char* prefix : {"/proc", "/sys", "/dev"}) {
        const std::size_t length = std::char_traits<char>::length(prefix);
        if (path.compare(0, length, prefix) == 0 && (path.size() == length || path[length] == '/')) return true;
    }
    return false;
}

} // namespace

MountSandbox::MountSandbox(const FileAccess& access) {
    if (!access.confine) return;
    m_valid = true;
    std::error_code error;
    auto existing = [&](const std::vector<std::filesystem::path>& paths) {
        std::vector<std::filesystem::path> out;
        for (const std::filesystem::path& path : paths)
            if (std::filesystem::exists(path, error)) out.push_back(normalPath(path));
        return out;
    };
    const std::vector<std::filesystem::path> writable = existing(access.writable);
    std::vector<std::filesystem::path> granted = existing(access.readable);
    std::vector<std::filesystem::path> devices = existing(access.devices);
    granted.insert(granted.end(), devices.begin(), devices.end());

    // The covers: excluded folders, outermost only, none that is itself granted.
    std::vector<std::filesystem::path> covers;
    for (const std::filesystem::path& path : existing(access.excluded)) {
        if (!std::filesystem::is_directory(path, error)) continue;
        if (std::find(granted.begin(), granted.end(), path) != granted.end()) continue;
        if (std::find(writable.begin(), writable.end(), path) != writable.end()) continue;
        covers.push_back(path);
    }
    std::sort(covers.begin(), covers.end());
    covers.erase(std::unique(covers.begin(), covers.end()), covers.end());
    std::vector<std::filesystem::path> outermost;
    for (const std::filesystem::path& path : covers)
        if (std::none_of(outermost.begin(), outermost.end(), [&](const auto& outer) { return below(path, outer); }))
            outermost.push_back(path);

    auto underCover = [&](const std::filesystem::path& path) {
        return std::any_of(outermost.begin(), outermost.end(), [&](const auto& cover) { return below(path, cover); });
    };
    for (const std::filesystem::path& path : writable)
        if (!underCover(path)) m_writable.push_back(path.string());

    for (const std::filesystem::path& coverPath : outermost) {
        Cover cover;
        cover.path = coverPath.string();
        std::vector<std::pair<std::filesystem::path, bool>> inside;   // path, writable
        for (const std::filesystem::path& path : granted)
            if (below(path, coverPath)) inside.emplace_back(path, false);
        for (const std::filesystem::path& path : writable)
            if (below(path, coverPath)) inside.emplace_back(path, true);
        std::sort(inside.begin(), inside.end(), [](const auto& a, const auto& b) {
            return std::distance(a.first.begin(), a.first.end()) < std::distance(b.first.begin(), b.first.end());
        });
        for (const auto& [path, canWrite] : inside) {
            Bind bind;
            bind.source = path.string();
            bind.target = path.string();
            bind.writable = canWrite;
            bind.isFolder = std::filesystem::is_directory(path, error);
            bind.flags = keptFlags(bind.source) & ~static_cast<unsigned long>(MS_RDONLY);
            // The folders leading to it in the tmpfs, parents first.
            std::filesystem::path step = coverPath;
            std::filesystem::path relative = path.lexically_relative(coverPath);
            for (auto part = relative.begin(); part != relative.end(); ++part) {
                step /= *part;
                const bool last = std::next(part) == relative.end();
                if (last && !bind.isFolder) cover.files.push_back(step.string());
                else if (std::find(cover.folders.begin(), cover.folders.end(), step.string()) == cover.folders.end())
                    cover.folders.push_back(step.string());
            }
            cover.binds.push_back(bind);
        }
        m_covers.push_back(std::move(cover));
    }
    std::size_t binds = 0;
    for (const Cover& cover : m_covers) binds += cover.binds.size();
    m_descriptors.assign(binds, -1);

    for (const std::string& point : mountPoints()) {
        if (underCover(point)) continue;
        if (std::find(m_writable.begin(), m_writable.end(), point) != m_writable.end()) continue;
        const unsigned long flags = keptFlags(point);
        if (flags & MS_RDONLY) continue;
        m_readOnly.push_back({point, flags});
    }
}

int MountSandbox::enter() const {
    // Open every path to bind back before anything covers it.
    std::size_t next = 0;
    for (const Cover& cover : m_covers)
        for (const Bind& bind : cover.binds) m_descriptors[next++] = open(bind.source.c_str(), O_PATH | O_CLOEXEC);
    for (const std::string& path : m_writable)
        if (mount(path.c_str(), path.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return errno;
    next = 0;
    for (const Cover& cover : m_covers) {
        if (mount("tmpfs", cover.path.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "mode=0755,size=1m") != 0) return errno;
        for (const std::string& folder : cover.folders) mkdir(folder.c_str(), 0755);
        for (const std::string& file : cover.files) {
            int fd = open(file.c_str(), O_CREAT | O_WRONLY | O_CLOEXEC, 0644);
            if (fd >= 0) close(fd);
        }
        for (const Bind& bind : cover.binds) {
            const int fd = m_descriptors[next++];
            if (fd < 0) continue;
            // "/proc/self/fd/N" names the opened path, now hidden under the tmpfs.
            char source[32] = "/proc/self/fd/";
            char digits[12];
            int length = 0;
            for (int value = fd; value > 0 || length == 0; value /= 10) digits[length++] = static_cast<char>('0' + value % 10);
            for (int i = 0; i < length; ++i) source[14 + i] = digits[length - 1 - i];
            source[14 + length] = '\0';
            if (mount(source, bind.target.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return errno;
            if (!bind.writable &&
                mount(nullptr, bind.target.c_str(), nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY | bind.flags, nullptr) != 0)
                return errno;
            close(fd);
        }
        if (mount(nullptr, cover.path.c_str(), nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY | MS_NOSUID | MS_NODEV,
                  nullptr) != 0)
            return errno;
    }
    // Everything else read-only; what the kernel will not remount under /proc,
    // /sys and /dev (masked or locked entries of a container) stays as it is.
    for (const ReadOnly& entry : m_readOnly)
        if (mount(nullptr, entry.path.c_str(), nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY | entry.flags, nullptr) != 0 &&
            !isPseudo(entry.path))
            return errno;
    return 0;
}

} // namespace stoa::grader
