#pragma once
// Reading the tests of a results.json as stoa-grade writes it (ResultsJson.hpp):
// each test is named "<lab>/<case>" ("<lab>/<case> [cascade]" for a cascade run,
// "<lab>/build" for a lab that did not compile) and tagged with its lab and its
// stoa-grade status; Gradescope's own "status" knows only passed and failed.
// The gradebook and the class report read the same tests through these.

#include "BatchGradeJson.hpp"

#include <string>

namespace stoa::grader {

/// The test's lab: its tag that starts with a digit ("01_transforms"), else the
/// part of its name before '/'.
std::string labOfTest(const JsonValue& test);

/// The case a test names, without the lab and the " [cascade]" mark: "orbit_front".
std::string caseOfTest(const JsonValue& test);

/// Whether the test carries the tag `wanted` ("cascade", "not counted").
bool hasTag(const JsonValue& test, const std::string& wanted);

/// stoa-grade's status of the test ("passed", "failed", "not attempted", "error",
/// "no reference"), from its tags; Gradescope's "status" when no tag names one.
std::string testStatus(const JsonValue& test);

/// A number member of `object`; `fallback` when it is absent or not a number.
double numberMember(const JsonValue& object, const std::string& name, double fallback = 0.0);

/// A string member of `object`; "" when it is absent or not a string.
std::string stringMember(const JsonValue& object, const std::string& name);

} // namespace stoa::grader
