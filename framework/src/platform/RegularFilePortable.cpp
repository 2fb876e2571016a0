// RegularFile where POSIX is missing (Windows): the file's type from
// std::filesystem::status(), its bytes through a std::ifstream. Windows has
// no FIFO or device that a path names in the file system, so checking the
// type once, before opening, is enough there.
#include <stoa/platform/RegularFile.hpp>

#ifdef _WIN32

#include "FileMessages.hpp"

#include <stoa/core/InputError.hpp>

#include <fstream>

namespace stoa::platform {

namespace fs = std::filesystem;

struct RegularFile::Handle {
    std::ifstream stream;
};

RegularFile::RegularFile(const fs::path& path, const char* kind)
    : m_name(path.string()), m_handle(std::make_unique<Handle>()) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error || status.type() == fs::file_type::not_found) {
        throw InputError(m_name, 0,
                         describeOpenError(error ? error : std::make_error_code(std::errc::no_such_file_or_directory)));
    }
    if (status.type() != fs::file_type::regular) {
        throw InputError(m_name, 0, "this is " + describeFileType(status.type()) + ", not " + kind);
    }
    m_size = fs::file_size(path, error);
    if (error) throw InputError(m_name, 0, describeOpenError(error));
    m_handle->stream.open(path, std::ios::binary);
    if (!m_handle->stream) {
        throw InputError(m_name, 0, "the file cannot be opened (it may be open in another program, or not readable)");
    }
}

RegularFile::~RegularFile() = default;

std::size_t RegularFile::read(char* into, std::size_t count) {
    std::ifstream& stream = m_handle->stream;
    if (stream.eof()) return 0;
    stream.read(into, static_cast<std::streamsize>(count));
    if (stream.bad()) throw InputError(m_name, 0, "the file cannot be read");
    return static_cast<std::size_t>(stream.gcount());
}

} // namespace stoa::platform

#endif
