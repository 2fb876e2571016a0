#include "XmlText.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cstdint>
#include <string_view>

namespace stoa {

namespace {

int lineAt(const std::string& text, std::size_t offset) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

/// The length of the UTF-8 sequence at `at`, or 0 when it is not one (overlong
/// forms, surrogates and code points past U+10FFFF included).
std::size_t utf8Length(std::string_view text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char first = byte(at);
    if (first < 0x80) return 1;
    std::size_t length = 0;
    std::uint32_t code = 0;
    if ((first & 0xE0) == 0xC0) length = 2, code = first & 0x1F;
    else if ((first & 0xF0) == 0xE0) length = 3, code = first & 0x0F;
    else if ((first & 0xF8) == 0xF0) length = 4, code = first & 0x07;
    else return 0;
    if (at + length > text.size()) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(at + i) & 0x3F);
    }
    const std::uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < least[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
    return length;
}

/// Whether XML 1.0 allows the character `code` in a document.
bool xmlCharacter(std::uint64_t code) {
    return code == 0x9 || code == 0xA || code == 0xD || (code >= 0x20 && code <= 0xD7FF) ||
           (code >= 0xE000 && code <= 0xFFFD) || (code >= 0x10000 && code <= 0x10FFFF);
}

/// The problem with the reference `&...;` starting at `text[at]`, or "".
std::string referenceProblem(std::string_view text, std::size_t at) {
    const std::size_t end = text.find(';', at);
    const std::string_view shown = text.substr(at, std::min<std::size_t>(end == std::string_view::npos ? 12 : end - at + 1, 24));
    if (end == std::string_view::npos || end - at > 16) {
        return "'" + std::string(shown) + "...' is not an entity reference: write & as &amp;";
    }
    const std::string_view body = text.substr(at + 1, end - at - 1);
    if (body == "amp" || body == "lt" || body == "gt" || body == "quot" || body == "apos") return "";
    if (body.size() >= 2 && body[0] == '#') {
        const bool hex = body[1] == 'x';
        const std::string_view digits = body.substr(hex ? 2 : 1);
        std::uint64_t code = 0;
        bool valid = !digits.empty();
        for (char c : digits) {
            int value = c >= '0' && c <= '9' ? c - '0' : -1;
            if (hex && c >= 'a' && c <= 'f') value = c - 'a' + 10;
            if (hex && c >= 'A' && c <= 'F') value = c - 'A' + 10;
            if (value < 0) valid = false;
            else if (code <= 0x10FFFF) code = code * (hex ? 16 : 10) + static_cast<std::uint64_t>(value);
        }
        if (!valid) return "'" + std::string(shown) + "' is not a character reference (&#65; or &#x41;)";
        if (!xmlCharacter(code)) return "'" + std::string(shown) + "' refers to a character XML does not allow in a file";
        return "";
    }
    return "the entity '" + std::string(shown) +
           "' is not defined: XML defines &amp;, &lt;, &gt;, &quot; and &apos;, and a file cannot define its own";
}

} // namespace

void checkXmlText(const std::string& text, const std::string& name) {
    const bool utf16Mark = text.size() >= 2 && ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF'));
    const bool utf16Zeros = text.size() >= 4 && ((text[0] == '<' && text[1] == '\0') || (text[0] == '\0' && text[1] == '<'));
    if (utf16Mark || utf16Zeros) throw InputError(name, 0, "the file is UTF-16; save it as UTF-8");
    const std::string_view view(text);
    for (std::size_t at = 0; at < view.size();) {
        const std::size_t length = utf8Length(view, at);
        if (length == 0) throw InputError(name, lineAt(text, at), "the file is not UTF-8 here (a byte of another encoding?); save it as UTF-8");
        if (view[at] == '\0') throw InputError(name, lineAt(text, at), "a NUL byte in the text");
        at += length;
    }
    // Entity references, outside what the parser skips.
    static constexpr std::pair<std::string_view, std::string_view> kSkipped[] = {
        {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}, {"<!DOCTYPE", ">"}};
    for (std::size_t at = 0; at < view.size(); ++at) {
        if (view[at] == '<') {
            for (const auto& [open, close] : kSkipped) {
                if (view.compare(at, open.size(), open) != 0) continue;
                const std::size_t end = view.find(close, at + open.size());
                at = end == std::string_view::npos ? view.size() : end + close.size() - 1;
                break;
            }
        } else if (view[at] == '&') {
            const std::string problem = referenceProblem(view, at);
            if (!problem.empty()) throw InputError(name, lineAt(text, at), problem);
        }
    }
}

} // namespace stoa
