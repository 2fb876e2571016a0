#include "Escape.hpp"

#include <cstdint>

namespace stoa::grader {

namespace {

const char* const kReplacement = "\xEF\xBF\xBD";   // U+FFFD in UTF-8

// The length of the valid UTF-8 sequence at text[i] whose code point XML 1.0
// allows, or 0 (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF).
std::size_t validSequence(const std::string& text, std::size_t i) {
    auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
    std::uint8_t lead = byte(i);
    if (lead < 0x80) {
        bool allowed = lead >= 0x20 || lead == '\t' || lead == '\n' || lead == '\r';
        return allowed && lead != 0x7F ? 1 : 0;
    }
    std::size_t length = 0;
    std::uint32_t codePoint = 0;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
        codePoint = lead & 0x1F;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        codePoint = lead & 0x0F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        codePoint = lead & 0x07;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        codePoint = (codePoint << 6) | (byte(i + k) & 0x3F);
    }
    static const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (codePoint < smallest[length] || codePoint > 0x10FFFF) return 0;
    if (codePoint >= 0xD800 && codePoint <= 0xDFFF) return 0;
    if (codePoint == 0xFFFE || codePoint == 0xFFFF) return 0;
    if (codePoint >= 0x80 && codePoint <= 0x9F) return 0;   // C1 controls: legal but never meant
    return length;
}

std::string escaped(const std::string& text, const char* apostrophe) {
    std::string clean = sanitizedText(text);
    std::string out;
    out.reserve(clean.size() + clean.size() / 8);
    for (char c : clean) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += apostrophe; break;
        default: out += c;
        }
    }
    return out;
}

} // namespace

std::string sanitizedText(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        std::size_t length = validSequence(text, i);
        if (length == 0) {
            out += kReplacement;
            ++i;
        } else {
            out.append(text, i, length);
            i += length;
        }
    }
    return out;
}

std::string htmlEscape(const std::string& text) { return escaped(text, "&#39;"); }

std::string xmlEscape(const std::string& text) { return escaped(text, "&apos;"); }

} // namespace stoa::grader
