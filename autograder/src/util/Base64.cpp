#include "Base64.hpp"

#include <fstream>
#include <sstream>

namespace stoa::grader {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

} // namespace

std::string base64Encode(const std::uint8_t* data, std::size_t size) {
    std::string text;
    text.reserve((size + 2) / 3 * 4);
    std::size_t i = 0;
    // Each group of three bytes (24 bits) becomes four 6-bit digits.
    for (; i + 3 <= size; i += 3) {
        std::uint32_t group = (std::uint32_t(data[i]) << 16) | (std::uint32_t(data[i + 1]) << 8) | data[i + 2];
        text += kAlphabet[(group >> 18) & 63];
        text += kAlphabet[(group >> 12) & 63];
        text += kAlphabet[(group >> 6) & 63];
        text += kAlphabet[group & 63];
    }
    // One or two bytes left: pad the group with zero bits and the digits with '='.
    std::size_t left = size - i;
    if (left > 0) {
        std::uint32_t group = std::uint32_t(data[i]) << 16;
        if (left == 2) group |= std::uint32_t(data[i + 1]) << 8;
        text += kAlphabet[(group >> 18) & 63];
        text += kAlphabet[(group >> 12) & 63];
        text += left == 2 ? kAlphabet[(group >> 6) & 63] : '=';
        text += '=';
    }
    return text;
}

std::string base64Encode(const std::string& bytes) {
    return base64Encode(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

std::string fileDataUri(const std::filesystem::path& path, const std::string& mimeType) {
    if (path.empty()) return "";
    std::ifstream file(path, std::ios::binary);
    if (!file) return "";
    std::ostringstream bytes;
    bytes << file.rdbuf();
    if (bytes.str().empty()) return "";
    return "data:" + mimeType + ";base64," + base64Encode(bytes.str());
}

} // namespace stoa::grader
