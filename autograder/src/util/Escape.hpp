#pragma once
// Text made safe for the HTML and XML reports. A lab program's output is
// arbitrary bytes (a student may print anything), so besides the markup
// characters this replaces what XML 1.0 cannot carry at all: control
// characters other than tab, newline and carriage return, and bytes that are
// not valid UTF-8 (each becomes U+FFFD, the replacement character).

#include <string>

namespace stoa::grader {

/// `text` as valid UTF-8 without control characters other than \t \n \r.
std::string sanitizedText(const std::string& text);

/// sanitizedText() with & < > " ' escaped, for element text and attribute values.
std::string htmlEscape(const std::string& text);

/// The same escaping for XML (&apos; for the apostrophe, which HTML 4 lacks).
std::string xmlEscape(const std::string& text);

} // namespace stoa::grader
