#pragma once
// Decoding one UTF-8 sequence, for the reports that must carry a lab
// program's output (arbitrary bytes) as valid text: JSON, HTML and XML.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace stoa::grader {

/// The length (1 to 4) of the well-formed UTF-8 sequence at text[i], or 0 when
/// it is not one (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF,
/// no sequence cut off by the end of `text`). Its code point goes to
/// `codePoint` when that is not null. `i` must be < text.size().
std::size_t utf8SequenceLength(std::string_view text, std::size_t i, std::uint32_t* codePoint = nullptr);

} // namespace stoa::grader
