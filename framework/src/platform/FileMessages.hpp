#pragma once
// Words for what went wrong with a file, the same on every platform: the
// messages of readInputFile (core/InputFile.hpp) through RegularFile.

#include <filesystem>
#include <string>
#include <system_error>

namespace stoa::platform {

/// What a path that is not a regular file is, for "this is a FIFO ..., not an OBJ file".
std::string describeFileType(std::filesystem::file_type type);

/// Why a file cannot be opened for reading ("the file does not exist").
std::string describeOpenError(const std::error_code& error);

} // namespace stoa::platform
