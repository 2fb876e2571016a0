#pragma once
// What a lab stub throws. The grader tells "not attempted" (this exception)
// apart from "wrong" (an image that does not match) and from a crash.

#include <stdexcept>
#include <string>

// The lab whose student files are being compiled: the build defines it for
// each of them (StoaLab.cmake), so that a stub says which lab it belongs to.
#ifndef STOA_STUDENT_LAB
#define STOA_STUDENT_LAB ""
#endif

namespace stoa {

class NotImplemented : public std::logic_error {
public:
    /// `function` names the stub as a student would search for it,
    /// e.g. "Camera::viewMatrix()". `lab` is the lab whose files throw it
    /// (taken where the stub is compiled); "" outside the labs.
    explicit NotImplemented(std::string function, std::string lab = STOA_STUDENT_LAB);

    const std::string& function() const { return m_function; }
    const std::string& lab() const { return m_lab; }

    /// What a lab program says of it: the function, and its lab when that is
    /// not `runningLab` ("forward(FirstPersonState) (lab 01_transforms)"),
    /// so that a student sees which earlier lab a later one waits for.
    std::string describe(const std::string& runningLab) const;

private:
    std::string m_function;
    std::string m_lab;
};

} // namespace stoa
