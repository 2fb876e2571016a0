// Polling, on every platform: what a file's modification time and size were
// at the previous look, compared with what they are now.
#include <stoa/platform/FileChangeSource.hpp>

#include <cstdint>
#include <filesystem>
#include <system_error>

namespace stoa::platform {

namespace fs = std::filesystem;

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

class PollingSource final : public FileChangeSource {
public:
    void watch(const std::string& file) override {
        m_files.push_back(file);
        m_stamps.push_back(stampOf(file));
    }

    void collect(std::vector<bool>& changed) override {
        // A file counts as changed when it exists and differs from what the
        // last poll saw; a file that went away is no change.
        for (std::size_t i = 0; i < m_files.size(); ++i) {
            const FileStamp stamp = stampOf(m_files[i]);
            if (stamp.exists && stamp != m_stamps[i]) changed[i] = true;
            m_stamps[i] = stamp;
        }
    }

    bool kernelNotified() const override { return false; }

private:
    std::vector<std::string> m_files;
    std::vector<FileStamp> m_stamps; // per file, as the last poll saw it
};

} // namespace

std::unique_ptr<FileChangeSource> makePollingSource() { return std::make_unique<PollingSource>(); }

} // namespace stoa::platform
