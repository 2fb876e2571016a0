#include <stoa/core/InputFile.hpp>

#include <stoa/core/InputError.hpp>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace stoa {

namespace {

/// What a path that is not a regular file is, for "... is a FIFO, not an OBJ file".
std::string describeType(mode_t mode) {
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe), which could block reading forever";
    if (S_ISCHR(mode)) return "a character device (such as /dev/zero), which could be read without end";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string describeErrno(int error) {
    switch (error) {
    case ENOENT: return "the file does not exist";
    case ENOTDIR: return "the file does not exist (a part of its path is not a folder)";
    case ELOOP: return "the path is a loop of symbolic links (too many levels of symbolic links)";
    case ENAMETOOLONG: return "the file name is too long for the system (a part of the path has over 255 bytes, "
                              "or the whole path is too long)";
    case EACCES: return "permission denied: the file cannot be read";
    default: return std::string("the file cannot be opened: ") + std::strerror(error);
    }
}

struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

std::string readInputFile(const std::filesystem::path& path, std::size_t maxBytes, const char* kind) {
    const std::string name = path.string();
    if (name.empty()) throw InputError(name, 0, std::string("no ") + kind + " was named (the path is empty)");
    if (name.find('\0') != std::string::npos) throw InputError(name, 0, "the file name contains a NUL byte");
    struct stat info {};
    if (::stat(name.c_str(), &info) != 0) throw InputError(name, 0, describeErrno(errno));
    if (!S_ISREG(info.st_mode)) {
        throw InputError(name, 0, "this is " + describeType(info.st_mode) + ", not " + kind);
    }
    // O_NONBLOCK: should a FIFO take the file's place after stat(), open() does not wait for a writer.
    Descriptor file{::open(name.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
    if (file.fd < 0) throw InputError(name, 0, describeErrno(errno));
    if (::fstat(file.fd, &info) != 0) throw InputError(name, 0, describeErrno(errno));
    if (!S_ISREG(info.st_mode)) {
        throw InputError(name, 0, "this is " + describeType(info.st_mode) + ", not " + kind);
    }
    auto tooLarge = [&](const std::string& size) {
        return InputError(name, 0, "the file is too large: " + size + " bytes, past the limit of " +
                                       std::to_string(maxBytes) + " bytes (" + std::to_string(maxBytes >> 20) +
                                       " MiB) for " + kind);
    };
    if (static_cast<unsigned long long>(info.st_size) > maxBytes) throw tooLarge(std::to_string(info.st_size));

    std::string bytes(static_cast<std::size_t>(info.st_size), '\0');
    std::size_t got = 0;
    // Read what stat promised, then one byte more to see whether the file grew meanwhile.
    for (;;) {
        if (got == bytes.size()) {
            if (bytes.size() > maxBytes) throw tooLarge("over " + std::to_string(maxBytes));
            bytes.resize(std::min(maxBytes + 1, bytes.size() + (std::size_t(1) << 16)));
        }
        const ssize_t n = ::read(file.fd, &bytes[got], bytes.size() - got);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError(name, 0, std::string("the file cannot be read: ") + std::strerror(errno));
        }
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    if (got > maxBytes) throw tooLarge("over " + std::to_string(maxBytes));
    bytes.resize(got);
    return bytes;
}

std::string quoteInput(const std::string& text, std::size_t maxBytes) {
    if (text.size() <= maxBytes) return text;
    std::size_t cut = maxBytes;
    // Do not cut a UTF-8 sequence in two.
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0u) == 0x80u) --cut;
    return text.substr(0, cut) + "...";
}

} // namespace stoa
