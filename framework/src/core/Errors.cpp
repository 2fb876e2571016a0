#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>

#include <cstdio>
#include <cstdlib>

namespace stoa {

static std::string describe(const std::string& file, int line, const std::string& message) {
    if (file.empty()) return message;
    if (line <= 0) return file + ": " + message;
    return file + ":" + std::to_string(line) + ": " + message;
}

InputError::InputError(std::string file, int line, std::string message)
    : std::runtime_error(describe(file, line, message)),
      m_file(std::move(file)), m_line(line), m_message(std::move(message)) {}

NotImplemented::NotImplemented(std::string function)
    : std::logic_error(function + " is not implemented yet"), m_function(std::move(function)) {}

namespace detail {
void assertionFailed(const char* condition, const char* message, const char* file, int line) {
    std::fprintf(stderr, "stoa: %s\n  (assertion `%s` failed at %s:%d)\n", message, condition, file, line);
    std::fflush(stderr);
    std::abort();
}
} // namespace detail

} // namespace stoa
