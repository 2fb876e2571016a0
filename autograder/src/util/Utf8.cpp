#include "Utf8.hpp"

namespace stoa::grader {

std::size_t utf8SequenceLength(std::string_view text, std::size_t i, std::uint32_t* codePoint) {
    auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
    std::uint8_t lead = byte(i);
    std::size_t length = 0;
    std::uint32_t point = 0;
    if (lead < 0x80) {
        length = 1;
        point = lead;
    } else if (lead >= 0xC2 && lead <= 0xDF) {   // 0xC0 and 0xC1 only start overlong forms
        length = 2;
        point = lead & 0x1F;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        point = lead & 0x0F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        point = lead & 0x07;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        point = (point << 6) | (byte(i + k) & 0x3F);
    }
    static const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (length > 1 && point < smallest[length]) return 0;
    if (point > 0x10FFFF || (point >= 0xD800 && point <= 0xDFFF)) return 0;
    if (codePoint) *codePoint = point;
    return length;
}

} // namespace stoa::grader
