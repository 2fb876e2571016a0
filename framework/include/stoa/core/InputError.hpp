#pragma once
// The one exception type for bad input at a load boundary: a model, an image,
// a shader, a case manifest, a command-line flag. It names the file and the
// line (0 when the problem concerns the whole file) and says what was expected.
// Programs catch it once, at the top, and print what() plainly. what() is
// safe to print whatever bytes the input held: control bytes (NUL included)
// and bytes that are not valid UTF-8 appear as \xNN; file(), line() and
// message() return what was given.

#include <stdexcept>
#include <string>

namespace stoa {

class InputError : public std::runtime_error {
public:
    /// `file` may be empty for input that has no file (a command-line flag).
    InputError(std::string file, int line, std::string message);

    const std::string& file() const { return m_file; }
    int line() const { return m_line; }             // 1-based; 0 = the whole file
    const std::string& message() const { return m_message; }

private:
    std::string m_file;
    int m_line;
    std::string m_message;
};

} // namespace stoa
