#pragma once
// The results as JUnit XML, the format CI systems (GitHub Actions test
// reporters, GitLab, Jenkins) show as test results:
//
//   <testsuites name="stoa-grade" tests="9" failures="1" errors="0" skipped="4" time="7.412">
//     <testsuite name="01_transforms" tests="5" failures="1" errors="0" skipped="0" time="4.100">
//       <testcase name="orbit_front" classname="01_transforms" time="0.812"/>
//       <testcase name="wide_lens" classname="01_transforms" time="0.790">
//         <failure message="4.20% pixels off (max 255, mean 9.3)" type="image mismatch">...</failure>
//       </testcase>
//       <testcase ...><error message="crashed with SIGSEGV" type="error">...</error></testcase>
//       <testcase ...><skipped message="not attempted"/></testcase>
//
// One suite per lab, one testcase per case (classname = the lab). A failed
// case's element text holds the hint and image paths; an error's holds the end
// of the program's output. "no reference" is an error (the case cannot grade).

#include "GradeResult.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

/// The document as text.
std::string junitXml(const std::vector<GradeResult>& results);

/// Writes junitXml() to `path` (its folder is created). Throws InputError when it cannot.
void writeJunitXml(const std::filesystem::path& path, const std::vector<GradeResult>& results);

} // namespace stoa::grader
