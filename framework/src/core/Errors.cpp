#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>

#include <cstdio>
#include <cstdlib>

namespace stoa {

namespace {

/// The length of the valid UTF-8 sequence at text[at] (2 to 4 bytes), or 0.
std::size_t utf8Sequence(const std::string& text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
    if (lead >= 0xC2 && lead <= 0xDF) length = 2;
    else if (lead >= 0xE0 && lead <= 0xEF) length = 3, low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
    else if (lead >= 0xF0 && lead <= 0xF4) length = 4, low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
    if (length == 0 || at + length > text.size()) return 0;
    if (byte(at + 1) < low || byte(at + 1) > high) return 0;
    for (std::size_t i = 2; i < length; ++i) {
        if ((byte(at + i) & 0xC0u) != 0x80u) return 0;
    }
    return length;
}

/// `text` safe to print: control bytes (NUL included) and bytes that are not
/// valid UTF-8 become \xNN, so what() is never cut short by a NUL and never
/// sends a terminal escape sequence. Newlines and tabs stay when `keepLines`.
std::string printable(const std::string& text, bool keepLines) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        if (keepLines && (c == '\n' || c == '\t')) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        if (c >= 0x80) {
            if (const std::size_t length = utf8Sequence(text, i)) {
                out.append(text, i, length);
                i += length;
                continue;
            }
        }
        static const char hex[] = "0123456789abcdef";
        out += "\\x";
        out += hex[c >> 4];
        out += hex[c & 15];
        ++i;
    }
    return out;
}

std::string describe(const std::string& file, int line, const std::string& message) {
    const std::string text = printable(message, true);
    if (file.empty()) return text;
    if (line <= 0) return printable(file, false) + ": " + text;
    return printable(file, false) + ":" + std::to_string(line) + ": " + text;
}

} // namespace

InputError::InputError(std::string file, int line, std::string message)
    : std::runtime_error(describe(file, line, message)),
      m_file(std::move(file)), m_line(line), m_message(std::move(message)) {}

NotImplemented::NotImplemented(std::string function, std::string lab)
    : std::logic_error(function + " is not implemented yet"), m_function(std::move(function)), m_lab(std::move(lab)) {}

std::string NotImplemented::describe(const std::string& runningLab) const {
    if (m_lab.empty() || m_lab == runningLab) return m_function;
    return m_function + " (lab " + m_lab + ")";
}

namespace detail {
void assertionFailed(const char* condition, const char* message, const char* file, int line) {
    std::fprintf(stderr, "stoa: %s\n  (assertion `%s` failed at %s:%d)\n", message, condition, file, line);
    std::fflush(stderr);
    std::abort();
}
} // namespace detail

} // namespace stoa
