// The kernel's notifications on Linux (inotify). The FOLDERS that hold the
// watched files are watched, not the files: an editor that saves by renaming
// a temporary file over the original would leave a watch on the file itself
// pointing at the old, unlinked copy (stoa/assets/FileWatcher.hpp says which
// events count as a change). Elsewhere makeKernelSource() offers nothing.
#include <stoa/platform/FileChangeSource.hpp>

#ifdef __linux__

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <system_error>
#include <unordered_map>

#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stoa::platform {

namespace fs = std::filesystem;

namespace {

bool fileExists(const std::string& file) {
    std::error_code error;
    (void)fs::last_write_time(file, error);
    return !error;
}

class InotifySource final : public FileChangeSource {
public:
    explicit InotifySource(int fd) : m_fd(fd) {}
    ~InotifySource() override {
        if (m_fd >= 0) close(m_fd);
    }
    InotifySource(const InotifySource&) = delete;
    InotifySource& operator=(const InotifySource&) = delete;

    void watch(const std::string& file) override {
        m_index.emplace(file, m_files.size());
        m_files.push_back(file);
        if (m_fd < 0) return;
        const std::string folder = fs::path(file).parent_path().string();
        auto [place, added] = m_folders.try_emplace(folder);
        place->second.files.push_back(m_files.size() - 1);
        if (added) addWatch(folder, place->second, nullptr);
    }

    void collect(std::vector<bool>& changed) override {
        if (m_fd < 0) return;
        readEvents(changed);
        retryLostFolders(changed);
    }

    bool kernelNotified() const override { return m_fd >= 0; }
    std::string failure() const override { return m_failure; }

private:
    /// A watched folder: its inotify watch (-1 while it has none, e.g. the
    /// folder does not exist) and the numbers of the watched files in it.
    struct Folder {
        int wd = -1;
        std::vector<std::size_t> files;
    };

    /// Adds the watch of `folder`. With `changed`, the folder has just
    /// appeared: files written into it before the watch existed count as changed.
    void addWatch(const std::string& folder, Folder& entry, std::vector<bool>* changed) {
        const std::uint32_t mask =
            IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE_SELF | IN_MOVE_SELF | IN_ONLYDIR;
        const int wd = inotify_add_watch(m_fd, folder.c_str(), mask);
        if (wd < 0) {
            // A folder that does not exist (yet) is retried at each poll; any
            // other failure (ENOSPC: the limit of watches) ends this source.
            if (errno != ENOENT && errno != ENOTDIR) {
                fail("inotify cannot watch " + folder + " (" + std::strerror(errno) + ")");
            }
            return;
        }
        entry.wd = wd;
        m_folderOfWatch[wd] = folder;
        if (!changed) return;
        for (std::size_t index : entry.files) {
            if (fileExists(m_files[index])) (*changed)[index] = true;
        }
    }

    void readEvents(std::vector<bool>& changed) {
        alignas(inotify_event) char buffer[16 * 1024];
        while (m_fd >= 0) {
            const ssize_t count = read(m_fd, buffer, sizeof buffer);
            if (count < 0 && errno == EINTR) continue;
            if (count <= 0) return; // EAGAIN: nothing more to read
            for (ssize_t at = 0; at < count;) {
                const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
                handle(*event, changed);
                at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            }
        }
    }

    void handle(const inotify_event& event, std::vector<bool>& changed) {
        if (event.mask & IN_Q_OVERFLOW) {
            // The kernel dropped events: any watched file may have changed.
            for (std::size_t i = 0; i < m_files.size(); ++i) changed[i] = true;
            return;
        }
        const auto folderName = m_folderOfWatch.find(event.wd);
        if (folderName == m_folderOfWatch.end()) return; // a watch already dropped
        const std::string folder = folderName->second;
        if (event.mask & (IN_DELETE_SELF | IN_MOVE_SELF | IN_IGNORED)) {
            // The folder went (or, renamed, is no longer at its path): drop the
            // watch and take it up again when a folder of that name exists.
            if (event.mask & IN_MOVE_SELF) inotify_rm_watch(m_fd, event.wd);
            m_folderOfWatch.erase(folderName);
            m_folders[folder].wd = -1;
            return;
        }
        if (event.len == 0) return;
        const std::string file = (fs::path(folder) / event.name).string();
        const auto index = m_index.find(file);
        if (index == m_index.end()) return; // another file in the folder
        if ((event.mask & IN_CREATE) && !isCompleteOnCreation(file)) return;
        changed[index->second] = true;
    }

    /// A regular file that was just created is being written: its
    /// IN_CLOSE_WRITE will report it. A symbolic link, or a hard link to a
    /// file that exists already, is complete at once.
    static bool isCompleteOnCreation(const std::string& file) {
        struct stat info {};
        if (lstat(file.c_str(), &info) != 0) return false;
        return !S_ISREG(info.st_mode) || info.st_nlink > 1;
    }

    void retryLostFolders(std::vector<bool>& changed) {
        for (auto& [folder, entry] : m_folders) {
            if (m_fd < 0) return;
            if (entry.wd >= 0) continue;
            std::error_code error;
            if (fs::is_directory(folder, error)) addWatch(folder, entry, &changed);
        }
    }

    void fail(const std::string& reason) {
        m_failure = reason;
        if (m_fd >= 0) close(m_fd);
        m_fd = -1;
    }

    int m_fd; // the inotify descriptor; -1 once the source failed
    std::string m_failure;
    std::vector<std::string> m_files;
    std::unordered_map<std::string, std::size_t> m_index; // file -> its number
    std::map<std::string, Folder> m_folders;
    std::unordered_map<int, std::string> m_folderOfWatch;
};

} // namespace

std::unique_ptr<FileChangeSource> makeKernelSource(std::string& why) {
    const int fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd < 0) {
        why = "inotify_init1() failed (" + std::string(std::strerror(errno)) + ")";
        return nullptr;
    }
    return std::make_unique<InotifySource>(fd);
}

} // namespace stoa::platform

#else

namespace stoa::platform {

std::unique_ptr<FileChangeSource> makeKernelSource(std::string&) { return nullptr; }

} // namespace stoa::platform

#endif
