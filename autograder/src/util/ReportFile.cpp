#include "ReportFile.hpp"

#include <stoa/core/InputError.hpp>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stoa::grader {

namespace {

// Writes all of `text` to `fd`; false with errno set when it cannot.
bool writeAll(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        ssize_t count = ::write(fd, text.data() + done, text.size() - done);
        if (count < 0 && errno == EINTR) continue;
        if (count <= 0) return false;
        done += static_cast<std::size_t>(count);
    }
    return true;
}

} // namespace

void writeReportFile(const std::filesystem::path& path, const std::string& text, const std::string& what) {
    if (path.filename().empty())
        throw InputError(path.string(), 0, "cannot write " + what + ": the path names a folder, not a file");
    std::error_code ignored;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ignored);
    // Beside the report, so that the rename stays on one file system.
    std::string temporary = (path.parent_path() / ("." + path.filename().string() + ".XXXXXX")).string();
    int fd = mkostemp(temporary.data(), O_CLOEXEC);
    if (fd < 0) throw InputError(path.string(), 0, "cannot write " + what + ": " + std::strerror(errno));
    bool written = writeAll(fd, text) && fchmod(fd, 0644) == 0;
    int error = errno;
    if (::close(fd) != 0 && written) {
        written = false;
        error = errno;
    }
    if (written && std::rename(temporary.c_str(), path.c_str()) == 0) return;
    if (written) error = errno;
    ::unlink(temporary.c_str());
    throw InputError(path.string(), 0,
                     "cannot write " + what + ": " + std::strerror(error) + (error == ENOSPC ? " (disk full?)" : ""));
}

} // namespace stoa::grader
