#include <stoa/assets/FileWatcher.hpp>

#include <stoa/platform/FileChangeSource.hpp>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <unordered_map>
#include <utility>

namespace fs = std::filesystem;

namespace stoa {

double steadySeconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

namespace {

/// STOA_FILE_WATCHER=polling asks for polling where the kernel's notifications
/// exist but miss changes (a network file system; Windows drives seen from WSL).
bool pollingRequested() {
    const char* const choice = std::getenv("STOA_FILE_WATCHER");
    return choice && std::strcmp(choice, "polling") == 0;
}

} // namespace

// The list of watched files and which changed; a platform source
// (platform/FileChangeSource.hpp) tells which did.
class FileWatcher::State {
public:
    explicit State(Backend backend) {
        if (backend == Backend::Automatic && !pollingRequested()) {
            std::string why;
            m_source = platform::makeKernelSource(why);
            if (!m_source && !why.empty()) logPolling(why);
        }
        if (!m_source) m_source = platform::makePollingSource();
    }

    void watch(const std::string& file) {
        if (m_index.count(file)) return;
        m_index.emplace(file, m_files.size());
        m_files.push_back(file);
        m_changed.push_back(false);
        m_source->watch(file);
        pollIfSourceFailed();
    }

    void collect() {
        m_source->collect(m_changed);
        pollIfSourceFailed();
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

    bool usesInotify() const { return m_source->kernelNotified(); }
    const std::vector<std::string>& files() const { return m_files; }
    std::vector<std::string> takeLog() { return std::exchange(m_log, {}); }

private:
    /// When the kernel's source stopped working, polling takes over; from now
    /// on changes are differences from the files as they are now. Changes the
    /// source reported before it failed are still reported.
    void pollIfSourceFailed() {
        const std::string why = m_source->failure();
        if (why.empty()) return;
        logPolling(why);
        m_source = platform::makePollingSource();
        for (const std::string& file : m_files) m_source->watch(file);
    }

    void logPolling(const std::string& why) {
        m_log.push_back("FileWatcher: " + why + "; polling modification times instead");
    }

    std::unique_ptr<platform::FileChangeSource> m_source;
    std::vector<std::string> m_files;
    std::unordered_map<std::string, std::size_t> m_index; // file -> index into m_files
    std::vector<bool> m_changed;                          // per file, since the last poll
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
