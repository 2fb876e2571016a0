#pragma once
// Reading a whole input file (a model, an image, a height map) into memory
// without ever blocking or reading without end: only regular files are
// opened, and never more than a stated number of bytes is read.

#include <cstddef>
#include <filesystem>
#include <string>

namespace stoa {

/// Reads the regular file at `path` (symbolic links followed) into a string.
/// `kind` names what the caller expects ("OBJ file", "image") for messages.
/// Throws InputError(path, 0, ...) that names the real cause when the path
/// does not exist, is a folder, a FIFO (named pipe), a character or block
/// device (/dev/zero), a socket, a symbolic link loop, has a name too long for
/// the system, cannot be opened (permissions), or holds more than `maxBytes`
/// bytes. The file is opened non-blocking and its type checked again on the
/// open descriptor, so a FIFO swapped in after the first check cannot block
/// either. At most maxBytes + 1 bytes are ever read.
std::string readInputFile(const std::filesystem::path& path, std::size_t maxBytes, const char* kind);

/// Text for a message quoting input: at most `maxBytes` bytes of `text`,
/// with "..." when it was cut. InputError::what() escapes the bytes.
std::string quoteInput(const std::string& text, std::size_t maxBytes = 40);

} // namespace stoa
