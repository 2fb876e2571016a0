#include <stoa/assets/FileWatcher.hpp>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <map>
#include <system_error>
#include <unordered_map>
#include <utility>

#ifdef __linux__
#include <cerrno>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace fs = std::filesystem;

namespace stoa {

double steadySeconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

namespace {

/// What polling compares: a file's modification time and size.
struct FileStamp {
    bool exists = false;
    fs::file_time_type modified{};
    std::uintmax_t size = 0;

    bool operator==(const FileStamp& other) const {
        return exists == other.exists && modified == other.modified && size == other.size;
    }
    bool operator!=(const FileStamp& other) const { return !(*this == other); }
};

FileStamp stampOf(const std::string& file) {
    std::error_code error;
    FileStamp stamp;
    stamp.modified = fs::last_write_time(file, error);
    if (error) return stamp;
    stamp.exists = true;
    stamp.size = fs::file_size(file, error);
    if (error) stamp.size = 0;
    return stamp;
}

} // namespace

class FileWatcher::State {
public:
    explicit State(Backend backend) {
#ifdef __linux__
        if (backend == Backend::Automatic) {
            m_fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
            if (m_fd < 0) usePolling("inotify_init1() failed (" + std::string(std::strerror(errno)) + ")");
        }
#else
        (void)backend;
#endif
    }

    ~State() {
#ifdef __linux__
        if (m_fd >= 0) close(m_fd);
#endif
    }
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    void watch(const std::string& file) {
        if (m_index.count(file)) return;
        m_index.emplace(file, m_files.size());
        m_files.push_back(file);
        m_changed.push_back(false);
        m_stamps.push_back(stampOf(file));
#ifdef __linux__
        if (m_fd < 0) return;
        const std::string folder = fs::path(file).parent_path().string();
        auto [place, added] = m_folders.try_emplace(folder);
        place->second.files.push_back(m_files.size() - 1);
        if (added) addWatch(folder, place->second, false);
#endif
    }

    void collect() {
#ifdef __linux__
        if (m_fd >= 0) {
            readEvents();
            retryLostFolders();
        }
#endif
        if (m_fd >= 0) return;
        // Polling: a file counts as changed when it exists and differs from
        // what the last poll saw; a file that went away is no change.
        for (std::size_t i = 0; i < m_files.size(); ++i) {
            const FileStamp stamp = stampOf(m_files[i]);
            if (stamp.exists && stamp != m_stamps[i]) m_changed[i] = true;
            m_stamps[i] = stamp;
        }
    }

    std::vector<FileChange> take(double now) {
        std::vector<FileChange> changes;
        for (std::size_t i = 0; i < m_files.size(); ++i) {
            if (!m_changed[i]) continue;
            changes.push_back({m_files[i], now});
            m_changed[i] = false;
        }
        return changes;
    }

    bool usesInotify() const { return m_fd >= 0; }
    const std::vector<std::string>& files() const { return m_files; }
    std::vector<std::string> takeLog() { return std::exchange(m_log, {}); }

private:
#ifdef __linux__
    /// A watched folder: its inotify watch (-1 while it has none, e.g. the
    /// folder does not exist) and the indices of the watched files in it.
    struct Folder {
        int wd = -1;
        std::vector<std::size_t> files;
    };

    /// Adds the watch of `folder`. When `reportFiles`, the folder has just
    /// appeared: files written into it before the watch existed count as changed.
    void addWatch(const std::string& folder, Folder& entry, bool reportFiles) {
        const std::uint32_t mask = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE_SELF | IN_MOVE_SELF | IN_ONLYDIR;
        const int wd = inotify_add_watch(m_fd, folder.c_str(), mask);
        if (wd < 0) {
            // A folder that does not exist (yet) is retried at each poll; any
            // other failure (ENOSPC: the limit of watches) means polling.
            if (errno != ENOENT && errno != ENOTDIR) {
                usePolling("inotify cannot watch " + folder + " (" + std::strerror(errno) + ")");
            }
            return;
        }
        entry.wd = wd;
        m_folderOfWatch[wd] = folder;
        if (!reportFiles) return;
        for (std::size_t index : entry.files) {
            if (stampOf(m_files[index]).exists) m_changed[index] = true;
        }
    }

    void readEvents() {
        alignas(inotify_event) char buffer[16 * 1024];
        while (m_fd >= 0) {
            const ssize_t count = read(m_fd, buffer, sizeof buffer);
            if (count < 0 && errno == EINTR) continue;
            if (count <= 0) return; // EAGAIN: nothing more to read
            for (ssize_t at = 0; at < count;) {
                const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
                handle(*event);
                at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            }
        }
    }

    void handle(const inotify_event& event) {
        if (event.mask & IN_Q_OVERFLOW) {
            // The kernel dropped events: any watched file may have changed.
            for (std::size_t i = 0; i < m_files.size(); ++i) m_changed[i] = true;
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
        m_changed[index->second] = true;
    }

    /// A regular file that was just created is being written: its
    /// IN_CLOSE_WRITE will report it. A symbolic link, or a hard link to a
    /// file that exists already, is complete at once.
    static bool isCompleteOnCreation(const std::string& file) {
        struct stat info {};
        if (lstat(file.c_str(), &info) != 0) return false;
        return !S_ISREG(info.st_mode) || info.st_nlink > 1;
    }

    void retryLostFolders() {
        for (auto& [folder, entry] : m_folders) {
            if (m_fd < 0) return;
            if (entry.wd >= 0) continue;
            std::error_code error;
            if (fs::is_directory(folder, error)) addWatch(folder, entry, true);
        }
    }

    std::map<std::string, Folder> m_folders;
    std::unordered_map<int, std::string> m_folderOfWatch;
#endif

    void usePolling(const std::string& reason) {
        m_log.push_back("FileWatcher: " + reason + "; polling modification times instead");
#ifdef __linux__
        if (m_fd >= 0) close(m_fd);
        m_fd = -1;
#endif
        // From now on changes are differences from the files as they are now.
        for (std::size_t i = 0; i < m_files.size(); ++i) m_stamps[i] = stampOf(m_files[i]);
    }

    int m_fd = -1; // the inotify descriptor; -1: polling
    std::vector<std::string> m_files;
    std::unordered_map<std::string, std::size_t> m_index; // file -> index into m_files
    std::vector<bool> m_changed;                          // per file, since the last poll
    std::vector<FileStamp> m_stamps;                      // per file, as the last poll saw it
    std::vector<std::string> m_log;
};

FileWatcher::FileWatcher(Backend backend, Clock clock)
    : m_state(std::make_unique<State>(backend)), m_clock(std::move(clock)) {}

FileWatcher::~FileWatcher() = default;
FileWatcher::FileWatcher(FileWatcher&& other) noexcept = default;
FileWatcher& FileWatcher::operator=(FileWatcher&& other) noexcept = default;

void FileWatcher::watch(const fs::path& path) { m_state->watch(normalPath(path)); }

std::vector<FileChange> FileWatcher::poll() { return poll(m_clock()); }

std::vector<FileChange> FileWatcher::poll(double now) {
    m_state->collect();
    return m_state->take(now);
}

bool FileWatcher::usesInotify() const { return m_state->usesInotify(); }
const std::vector<std::string>& FileWatcher::files() const { return m_state->files(); }
std::vector<std::string> FileWatcher::takeLog() { return m_state->takeLog(); }

std::string FileWatcher::normalPath(const fs::path& path) {
    std::error_code error;
    fs::path absolute = fs::absolute(path, error);
    if (error) absolute = path;
    return absolute.lexically_normal().string();
}

} // namespace stoa
