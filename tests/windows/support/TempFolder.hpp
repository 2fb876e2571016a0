#pragma once
// The Windows build's TempFolder (tests/windows/build-core-mingw.sh puts this
// folder first on the include path): the same class as
// tests/support/TempFolder.hpp, made with std::filesystem alone, since
// mkdtemp() and chmod() are POSIX. A fresh folder under the system's temporary
// folder, removed with everything in it when the object goes out of scope.

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace stoa::test {

class TempFolder {
public:
    /// `purpose` becomes part of the folder's name, to tell leftovers apart.
    explicit TempFolder(const std::string& purpose = "test") {
        static std::atomic<unsigned> counter{0};
        const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
        for (int attempt = 0; attempt < 100; ++attempt) {
            const std::string name = "stoa-" + purpose + "-" + std::to_string(now % 1000000007) + "-" +
                                     std::to_string(counter++);
            std::filesystem::path candidate = std::filesystem::temp_directory_path() / name;
            // create_directory() is false when the folder was there already: then another name.
            if (std::filesystem::create_directory(candidate)) {
                m_path = candidate;
                return;
            }
        }
        throw std::runtime_error("TempFolder: cannot make a folder for " + purpose);
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
    /// Windows has no executable bit: `executable` changes nothing there.
    std::filesystem::path write(const std::string& name, const std::string& text, bool executable = false) const {
        (void)executable;
        std::filesystem::path file = m_path / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

private:
    std::filesystem::path m_path;
};

} // namespace stoa::test
