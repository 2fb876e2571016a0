#pragma once
// Tells which of a set of files changed on disk since it was last asked. No
// OpenGL (part of stoa_core); the AssetCache polls one each frame.
//
//   FileWatcher watcher;
//   watcher.watch(paths::shadersDir() / "editor/lit.frag");
//   for (const FileChange& change : watcher.poll()) ...   // each frame
//
// On Linux it asks the kernel (inotify) and watches the FOLDERS that hold the
// files, not the files: editors save by writing a temporary file and renaming
// it over the original, which would leave a watch on the file itself pointing
// at the old, unlinked copy. A file counts as changed when, in its folder, it
// is closed after writing (IN_CLOSE_WRITE), renamed to its name (IN_MOVED_TO)
// or created (IN_CREATE, e.g. a new symbolic link). A file that is deleted or
// renamed away is not a change: there is nothing new to load, and the file
// coming back is one. When the folder itself goes (deleted or renamed), its
// watch is dropped and taken up again once a folder of that name exists,
// reporting every watched file in it. Other files in the folder are ignored.
//
// Elsewhere (Windows, macOS), where inotify fails (e.g. the system's limit of
// watches is reached), or when the environment variable STOA_FILE_WATCHER is
// "polling" (for folders whose changes the kernel does not see: a network file
// system, a Windows drive seen from WSL), it polls: each poll() compares every
// watched file's modification time and size with what it saw before. A switch
// after a failure is logged once (takeLog()). The platform's part lives in
// framework/src/platform/ (platform/FileChangeSource.hpp).

#include <stoa/assets/ReloadPlan.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace stoa {

/// Seconds on std::chrono::steady_clock (the FileWatcher's default clock).
double steadySeconds();

class FileWatcher {
public:
    enum class Backend {
        Automatic, // inotify on Linux, polling elsewhere, when inotify fails or STOA_FILE_WATCHER=polling
        Polling,   // compare modification times at each poll()
    };
    using Clock = std::function<double()>;

    /// `clock` stamps the changes poll() returns (seconds).
    explicit FileWatcher(Backend backend = Backend::Automatic, Clock clock = steadySeconds);
    ~FileWatcher();
    FileWatcher(const FileWatcher&) = delete;
    FileWatcher& operator=(const FileWatcher&) = delete;
    FileWatcher(FileWatcher&& other) noexcept;
    FileWatcher& operator=(FileWatcher&& other) noexcept;

    /// Watches the file at `path` (made absolute and lexically normal); watching
    /// it again does nothing. The file and its folder need not exist yet.
    void watch(const std::filesystem::path& path);

    /// The watched files that changed since the last poll() (or since they were
    /// watched), each once, stamped with the clock's time now; in the order
    /// they were watched. Never blocks.
    [[nodiscard]] std::vector<FileChange> poll();
    /// The same, stamped with `now`.
    [[nodiscard]] std::vector<FileChange> poll(double now);

    /// Whether the kernel reports the changes (false: polling).
    bool usesInotify() const;
    /// The watched files (absolute, lexically normal), in the order watched.
    const std::vector<std::string>& files() const;

    /// Lines worth showing in a log (the fall-back to polling), oldest first;
    /// taking them empties the list.
    std::vector<std::string> takeLog();

    /// `path` made absolute and lexically normal, as FileChange and AssetFiles spell files.
    static std::string normalPath(const std::filesystem::path& path);

private:
    class State;
    std::unique_ptr<State> m_state;
    Clock m_clock;
};

} // namespace stoa
