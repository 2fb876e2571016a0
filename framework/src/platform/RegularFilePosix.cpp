// RegularFile on POSIX: stat() before opening, and fstat() on the open
// descriptor, so that a FIFO put in the file's place in between cannot block.
#include <stoa/platform/RegularFile.hpp>

#ifndef _WIN32

#include "FileMessages.hpp"

#include <stoa/core/InputError.hpp>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stoa::platform {

namespace {

std::filesystem::file_type typeOf(mode_t mode) {
    using std::filesystem::file_type;
    if (S_ISREG(mode)) return file_type::regular;
    if (S_ISDIR(mode)) return file_type::directory;
    if (S_ISFIFO(mode)) return file_type::fifo;
    if (S_ISCHR(mode)) return file_type::character;
    if (S_ISBLK(mode)) return file_type::block;
    if (S_ISSOCK(mode)) return file_type::socket;
    return file_type::unknown;
}

std::error_code lastError() { return {errno, std::generic_category()}; }

} // namespace

struct RegularFile::Handle {
    int fd = -1;
    ~Handle() {
        if (fd >= 0) ::close(fd);
    }
};

RegularFile::RegularFile(const std::filesystem::path& path, const char* kind)
    : m_name(path.string()), m_handle(std::make_unique<Handle>()) {
    const auto refuseType = [&](mode_t mode) {
        return InputError(m_name, 0, "this is " + describeFileType(typeOf(mode)) + ", not " + kind);
    };
    struct stat info {};
    if (::stat(m_name.c_str(), &info) != 0) throw InputError(m_name, 0, describeOpenError(lastError()));
    if (!S_ISREG(info.st_mode)) throw refuseType(info.st_mode);
    // O_NONBLOCK: should a FIFO take the file's place after stat(), open() does not wait for a writer.
    m_handle->fd = ::open(m_name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (m_handle->fd < 0) throw InputError(m_name, 0, describeOpenError(lastError()));
    if (::fstat(m_handle->fd, &info) != 0) throw InputError(m_name, 0, describeOpenError(lastError()));
    if (!S_ISREG(info.st_mode)) throw refuseType(info.st_mode);
    m_size = static_cast<std::uint64_t>(info.st_size);
}

RegularFile::~RegularFile() = default;

std::size_t RegularFile::read(char* into, std::size_t count) {
    for (;;) {
        const ssize_t n = ::read(m_handle->fd, into, count);
        if (n >= 0) return static_cast<std::size_t>(n);
        if (errno == EINTR) continue;
        throw InputError(m_name, 0, std::string("the file cannot be read: ") + std::strerror(errno));
    }
}

} // namespace stoa::platform

#endif
