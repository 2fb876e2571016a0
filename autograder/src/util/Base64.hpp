#pragma once
// Base64 (RFC 4648, section 4: the standard alphabet with '=' padding, no line
// breaks), for embedding images in the HTML report as data URIs.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace stoa::grader {

/// The Base64 text of `size` bytes at `data` (4 characters per 3 bytes, padded).
std::string base64Encode(const std::uint8_t* data, std::size_t size);

/// The Base64 text of the bytes of `bytes`.
std::string base64Encode(const std::string& bytes);

/// "data:<mimeType>;base64,<the file's bytes>", or "" when the file cannot be read.
std::string fileDataUri(const std::filesystem::path& path, const std::string& mimeType = "image/png");

} // namespace stoa::grader
