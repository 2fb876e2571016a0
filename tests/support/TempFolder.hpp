#pragma once
// A fresh folder under the system's temporary folder, removed with everything
// in it when the object goes out of scope. Each test that writes files makes
// its own, so tests can run in parallel (ctest -j). The same on Windows (the
// MinGW build, tests/windows/), where mkdtemp() is missing.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#ifdef _WIN32
#include <atomic>
#include <chrono>
#endif

namespace stoa::test {

class TempFolder {
public:
    /// `purpose` becomes part of the folder's name, to tell leftovers apart.
    explicit TempFolder(const std::string& purpose = "test") {
#ifdef _WIN32
        // create_directory() is false when the folder was there already: then another name.
        static std::atomic<unsigned> counter{0};
        const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
        for (int attempt = 0; attempt < 100 && m_path.empty(); ++attempt) {
            const std::filesystem::path candidate = std::filesystem::temp_directory_path() /
                ("stoa-" + purpose + "-" + std::to_string(now % 1000000007) + "-" + std::to_string(counter++));
            if (std::filesystem::create_directory(candidate)) m_path = candidate;
        }
        if (m_path.empty()) throw std::runtime_error("TempFolder: cannot make a folder for " + purpose);
#else
        std::string pattern = (std::filesystem::temp_directory_path() / ("stoa-" + purpose + "-XXXXXX")).string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("TempFolder: mkdtemp failed for " + pattern);
        m_path = pattern;
#endif
    }
    ~TempFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(m_path, ignored);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const std::filesystem::path& path() const { return m_path; }
    std::filesystem::path operator/(const std::string& name) const { return m_path / name; }

    /// Writes `text` to path()/name (folders created) and returns the full path.
    /// (Windows has no executable bit: there `executable` changes nothing.)
    std::filesystem::path write(const std::string& name, const std::string& text, bool executable = false) const {
        std::filesystem::path file = m_path / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        if (executable) {
            using std::filesystem::perms;
            std::filesystem::permissions(file, perms::owner_all | perms::group_read | perms::group_exec |
                                                   perms::others_read | perms::others_exec);
        }
        return file;
    }

private:
    std::filesystem::path m_path;
};

} // namespace stoa::test
