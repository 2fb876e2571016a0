#pragma once
// Programming errors (misuse of the API, not bad input) stop the program with
// a message that names the function and says how to fix the call.
//
//   STOA_ASSERT(m_id != 0, "Program::use(): the program was moved from or released. "
//                          "Keep the Program object alive while you draw with it.");

namespace stoa::detail {
[[noreturn]] void assertionFailed(const char* condition, const char* message, const char* file, int line);
}

#define STOA_ASSERT(condition, message)                                                   \
    do {                                                                                  \
        if (!(condition)) ::stoa::detail::assertionFailed(#condition, message, __FILE__, __LINE__); \
    } while (false)
