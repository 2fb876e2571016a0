#include <stoa/core/InputFile.hpp>

#include <stoa/core/InputError.hpp>

#include <stoa/platform/RegularFile.hpp>

#include <algorithm>

namespace stoa {

std::string readInputFile(const std::filesystem::path& path, std::size_t maxBytes, const char* kind) {
    const std::string name = path.string();
    if (name.empty()) throw InputError(name, 0, std::string("no ") + kind + " was named (the path is empty)");
    if (name.find('\0') != std::string::npos) throw InputError(name, 0, "the file name contains a NUL byte");
    // Opening refuses what is not a regular file (platform/RegularFile.hpp).
    platform::RegularFile file(path, kind);
    auto tooLarge = [&](const std::string& size) {
        return InputError(name, 0, "the file is too large: " + size + " bytes, past the limit of " +
                                       std::to_string(maxBytes) + " bytes (" + std::to_string(maxBytes >> 20) +
                                       " MiB) for " + kind);
    };
    if (file.size() > maxBytes) throw tooLarge(std::to_string(file.size()));

    std::string bytes(static_cast<std::size_t>(file.size()), '\0');
    std::size_t got = 0;
    // Read what the size promised, then one byte more to see whether the file grew meanwhile.
    for (;;) {
        if (got == bytes.size()) {
            if (bytes.size() > maxBytes) throw tooLarge("over " + std::to_string(maxBytes));
            bytes.resize(std::min(maxBytes + 1, bytes.size() + (std::size_t(1) << 16)));
        }
        const std::size_t n = file.read(&bytes[got], bytes.size() - got);
        if (n == 0) break;
        got += n;
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
