#pragma once
// What a lab program tells the grader, in one place: its exit status and the
// lines it prints that the grader reads back. Both sides use these functions,
// so the words cannot drift apart (the grader runs the lab as a child process
// and links stoa_core only; this header needs nothing else).
//
//   lab program                               grader (autograder/src/run/)
//   exit kExitNotAttempted, prints            -> "not attempted", the reason
//     notImplementedLine("Camera::view()")       parseNotImplementedLine(last line)
//   exit kExitOk / kExitCheckFailed, prints   -> passed / failed, the reason
//     checkVerdictLine(name, verdict, text)      parseCheckVerdictLine(last line)

#include <optional>
#include <string>

namespace stoa {

/// A lab program's exit status.
enum ExitCode {
    kExitOk = 0,            // done: the picture is written, the check holds
    kExitError = 1,         // an error (bad case, bad file, a crash caught): the message is on stderr
    kExitUsage = 2,         // a bad command line
    kExitNotAttempted = 3,  // a stub is still in place (C++ NotImplemented or a GLSL STOA_NOT_IMPLEMENTED)
    kExitCheckFailed = 4,   // a property check does not hold (PropertyCheck.hpp)
};

/// "not implemented: WHAT": what a student sees (window, report) for a stub still in place.
std::string notImplementedText(const std::string& what);
/// "stoa: not implemented: WHAT": the line a lab prints on stderr before exiting kExitNotAttempted.
std::string notImplementedLine(const std::string& what);
/// WHAT from a notImplementedLine() or a line ending in notImplementedText(); nothing otherwise.
std::optional<std::string> parseNotImplementedLine(const std::string& line);

/// A property check's verdict, as the lab prints it.
enum class CheckVerdict { Holds, DoesNotHold, NotAttempted };

/// "check NAME: holds: MESSAGE" (or "does not hold", "not attempted"): printed on
/// stdout as a check's last line.
std::string checkVerdictLine(const std::string& name, CheckVerdict verdict, const std::string& message);

struct CheckVerdictLine {
    std::string name;
    CheckVerdict verdict = CheckVerdict::Holds;
    std::string message;
};
/// The parts of a checkVerdictLine(); nothing when `line` is not one.
std::optional<CheckVerdictLine> parseCheckVerdictLine(const std::string& line);

} // namespace stoa
