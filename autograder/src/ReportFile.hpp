#pragma once
// Writing a report file (results.json, the HTML report, the JUnit XML): the
// folder is created, and a write that fails says which report and why.

#include <filesystem>
#include <string>

namespace stoa::grader {

/// Writes `text` to `path`, creating its folder. `what` names the report in the
/// message ("the HTML report"). Throws InputError naming the path when it cannot.
void writeReportFile(const std::filesystem::path& path, const std::string& text, const std::string& what);

} // namespace stoa::grader
