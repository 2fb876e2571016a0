#pragma once
// Reading a regular file and nothing else: the platform's part of
// readInputFile (core/InputFile.hpp), which sets the limits. On POSIX the
// type is checked with stat() before opening and with fstat() on the open,
// non-blocking descriptor, so a FIFO swapped in meanwhile cannot block.
// Without POSIX (Windows) the type comes from std::filesystem::status() and
// the bytes from a std::ifstream.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace stoa::platform {

class RegularFile {
public:
    /// Opens `path` (symbolic links followed) for reading. `kind` names what
    /// the caller expects ("OBJ file") in "this is a folder, not an OBJ file".
    /// Throws InputError(path, 0, why) when the path does not exist, is not a
    /// regular file (a folder, a FIFO, a device, a socket) or cannot be opened.
    RegularFile(const std::filesystem::path& path, const char* kind);
    ~RegularFile();
    RegularFile(const RegularFile&) = delete;
    RegularFile& operator=(const RegularFile&) = delete;

    /// The file's size in bytes when it was opened (it may grow since).
    std::uint64_t size() const { return m_size; }

    /// Reads at most `count` bytes into `into`; returns how many, 0 at the
    /// end of the file. Throws InputError(path, 0, why) when reading fails.
    std::size_t read(char* into, std::size_t count);

private:
    struct Handle;
    std::string m_name;
    std::unique_ptr<Handle> m_handle;
    std::uint64_t m_size = 0;
};

} // namespace stoa::platform
