#pragma once
// A fresh folder under the system's temporary folder, removed with everything
// in it when the object goes out of scope. Each test that writes files makes
// its own, so tests can run in parallel (ctest -j).

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <sys/stat.h>

namespace stoa::test {

class TempFolder {
public:
    /// `purpose` becomes part of the folder's name, to tell leftovers apart.
    explicit TempFolder(const std::string& purpose = "test") {
        std::string pattern = (std::filesystem::temp_directory_path() / ("stoa-" + purpose + "-XXXXXX")).string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("TempFolder: mkdtemp failed for " + pattern);
        m_path = pattern;
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
    std::filesystem::path write(const std::string& name, const std::string& text, bool executable = false) const {
        std::filesystem::path file = m_path / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        if (executable) chmod(file.c_str(), 0755);
        return file;
    }

private:
    std::filesystem::path m_path;
};

} // namespace stoa::test
