#include "Escape.hpp"

#include "Utf8.hpp"

#include <cstdint>

namespace stoa::grader {

namespace {

const char* const kReplacement = "\xEF\xBF\xBD";   // U+FFFD in UTF-8

// The length of the well-formed UTF-8 sequence at text[i] whose code point
// XML 1.0 allows, or 0.
std::size_t validSequence(const std::string& text, std::size_t i) {
    std::uint32_t codePoint = 0;
    std::size_t length = utf8SequenceLength(text, i, &codePoint);
    if (length == 0) return 0;
    if (codePoint < 0x20) return codePoint == '\t' || codePoint == '\n' || codePoint == '\r' ? 1 : 0;
    if (codePoint == 0x7F || (codePoint >= 0x80 && codePoint <= 0x9F)) return 0;   // DEL, C1 controls
    if (codePoint == 0xFFFE || codePoint == 0xFFFF) return 0;
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
