#pragma once
// Where a FileWatcher (stoa/assets/FileWatcher.hpp) learns that its files changed:
// the platform's part of watching. The watcher keeps the list of files and
// the flags it reports; a source only marks which files changed.
//
// Two sources: the kernel's notifications (inotify, on Linux only) and
// polling (every platform: std::filesystem's modification time and size).

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace stoa::platform {

class FileChangeSource {
public:
    virtual ~FileChangeSource() = default;

    /// Watches `file` (absolute, lexically normal; its folder need not
    /// exist). Files are numbered in the order they are watched, from 0.
    virtual void watch(const std::string& file) = 0;

    /// Sets changed[n] for every file n that changed since the last call;
    /// never clears a flag. `changed` has one entry per watched file.
    virtual void collect(std::vector<bool>& changed) = 0;

    /// Whether the kernel reports the changes (false: polling).
    virtual bool kernelNotified() const = 0;

    /// Why the source stopped working (e.g. the system's limit of inotify
    /// watches was reached); empty while it works. The watcher then goes on
    /// with a polling source.
    virtual std::string failure() const { return {}; }
};

/// Polling: a file changed when it exists and its modification time or its
/// size differs from what the previous collect() (or watch()) saw. A file
/// that goes away is no change; its coming back is one.
std::unique_ptr<FileChangeSource> makePollingSource();

/// The kernel's notifications where the platform has them (inotify on
/// Linux). nullptr where it has none, and when they cannot be started: then
/// `why` says why (it stays empty where the platform has none).
std::unique_ptr<FileChangeSource> makeKernelSource(std::string& why);

} // namespace stoa::platform
