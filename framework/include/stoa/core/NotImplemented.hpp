#pragma once
// What a lab stub throws. The grader tells "not attempted" (this exception)
// apart from "wrong" (an image that does not match) and from a crash.

#include <stdexcept>
#include <string>

namespace stoa {

class NotImplemented : public std::logic_error {
public:
    /// `function` names the stub as a student would search for it,
    /// e.g. "Camera::viewMatrix()".
    explicit NotImplemented(std::string function);

    const std::string& function() const { return m_function; }

private:
    std::string m_function;
};

} // namespace stoa
