#include "JunitReport.hpp"

#include "Escape.hpp"
#include "ReportFile.hpp"

#include <algorithm>
#include <cstdio>

namespace stoa::grader {

namespace {

constexpr std::size_t kOutputBytesKept = 4096;

struct SuiteCounts {
    int tests = 0;
    int failures = 0;
    int errors = 0;
    int skipped = 0;
    double seconds = 0.0;

    void add(const GradeResult& result) {
        ++tests;
        seconds += result.seconds;
        if (result.status == GradeStatus::Failed) ++failures;
        if (result.status == GradeStatus::Error || result.status == GradeStatus::NoReference) ++errors;
        if (result.status == GradeStatus::NotAttempted) ++skipped;
    }

    std::string attributes() const {
        char time[32];
        std::snprintf(time, sizeof time, "%.3f", seconds);
        return " tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(failures) + "\" errors=\"" +
               std::to_string(errors) + "\" skipped=\"" + std::to_string(skipped) + "\" time=\"" + time + "\"";
    }
};

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}

// The end of a long output, so one noisy program does not bloat the report.
std::string tail(const std::string& output) {
    if (output.size() <= kOutputBytesKept) return output;
    return "[...]\n" + output.substr(output.size() - kOutputBytesKept);
}

// What a failed case's <failure> element says beyond its message.
std::string failureText(const GradeResult& result) {
    std::string text = result.reason + "\n";
    if (result.hasHint()) {
        text += "hint (looks like the known mistake " + result.hintMistake + "): " + result.hint + "\n";
        if (!result.hintDocs.empty()) text += "read: " + result.hintDocs + "\n";
    }
    if (!result.renderedImage.empty()) text += "yours:     " + result.renderedImage.string() + "\n";
    if (!result.referenceImage.empty()) text += "reference: " + result.referenceImage.string() + "\n";
    if (!result.heatMapImage.empty()) text += "heat map:  " + result.heatMapImage.string() + "\n";
    return text;
}

void writeCase(std::string& xml, const GradeResult& result) {
    xml += "    <testcase name=\"" + xmlEscape(result.caseName) + "\" classname=\"" + xmlEscape(result.lab) +
           "\" time=\"" + seconds(result.seconds) + "\"";
    switch (result.status) {
    case GradeStatus::Passed:
        xml += "/>\n";
        return;
    case GradeStatus::Failed:
        xml += ">\n      <failure message=\"" + xmlEscape(result.reason) + "\" type=\"image mismatch\">" +
               xmlEscape(failureText(result)) + "</failure>\n";
        break;
    case GradeStatus::NotAttempted:
        xml += ">\n      <skipped message=\"not attempted\">" + xmlEscape(result.reason) + "</skipped>\n";
        break;
    case GradeStatus::Error:
    case GradeStatus::NoReference:
        xml += ">\n      <error message=\"" + xmlEscape(result.reason) + "\" type=\"" +
               xmlEscape(statusName(result.status)) + "\">" + xmlEscape(result.reason) + "</error>\n";
        if (!result.programOutput.empty())
            xml += "      <system-out>" + xmlEscape(tail(result.programOutput)) + "</system-out>\n";
        break;
    }
    xml += "    </testcase>\n";
}

} // namespace

std::string junitXml(const std::vector<GradeResult>& results) {
    // Suites in the order the results first name their labs.
    std::vector<std::string> labs;
    for (const GradeResult& result : results)
        if (std::find(labs.begin(), labs.end(), result.lab) == labs.end()) labs.push_back(result.lab);

    SuiteCounts all;
    for (const GradeResult& result : results) all.add(result);
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites name=\"stoa-grade\"" + all.attributes() + ">\n";
    for (const std::string& lab : labs) {
        SuiteCounts suite;
        for (const GradeResult& result : results)
            if (result.lab == lab) suite.add(result);
        xml += "  <testsuite name=\"" + xmlEscape(lab) + "\"" + suite.attributes() + ">\n";
        for (const GradeResult& result : results)
            if (result.lab == lab) writeCase(xml, result);
        xml += "  </testsuite>\n";
    }
    xml += "</testsuites>\n";
    return xml;
}

void writeJunitXml(const std::filesystem::path& path, const std::vector<GradeResult>& results) {
    writeReportFile(path, junitXml(results), "the JUnit XML");
}

} // namespace stoa::grader
