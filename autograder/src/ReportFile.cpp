#include "ReportFile.hpp"

#include <stoa/core/InputError.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace stoa::grader {

void writeReportFile(const std::filesystem::path& path, const std::string& text, const std::string& what) {
    std::error_code ignored;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ignored);
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw InputError(path.string(), 0, "cannot write " + what + ": " + std::strerror(errno));
    file << text;
    file.close();
    if (!file) throw InputError(path.string(), 0, "cannot write " + what + " (disk full?)");
}

} // namespace stoa::grader
