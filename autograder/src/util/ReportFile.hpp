#pragma once
// Writing a report file (results.json, the HTML report, the JUnit XML, the
// gradebook): the folder is created, the text goes to a private temporary file
// beside the report (O_CLOEXEC, mode 0600 until it is complete), which is then
// renamed over the report in one step. A reader never sees half a report, and
// whatever a lab program put at the report's path before (a file, a link) is
// replaced, not written through. A write that fails says which report and why.

#include <filesystem>
#include <string>

namespace stoa::grader {

/// Writes `text` to `path`, creating its folder. `what` names the report in the
/// message ("the HTML report"). Throws InputError naming the path when it cannot;
/// `path` is then left as it was.
void writeReportFile(const std::filesystem::path& path, const std::string& text, const std::string& what);

} // namespace stoa::grader
