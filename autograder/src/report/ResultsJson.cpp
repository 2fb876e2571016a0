#include "ResultsJson.hpp"

#include "JsonWriter.hpp"
#include "ReportFile.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

namespace stoa::grader {

namespace {

// "1.3" for the third case of lab 01_*: the lab's number, then the case's place in it.
std::string testNumber(const std::string& lab, int labIndex, int caseIndex) {
    std::size_t digits = 0;
    while (digits < lab.size() && std::isdigit(static_cast<unsigned char>(lab[digits]))) ++digits;
    int labNumber = digits > 0 ? std::stoi(lab.substr(0, digits)) : labIndex;
    return std::to_string(labNumber) + "." + std::to_string(caseIndex);
}

std::string testOutput(const GradeResult& result) {
    std::string text = statusName(result.status);
    if (!result.reason.empty()) text += ": " + result.reason;
    text += "\n";
    if (result.cascade)
        text += "Rendered with the solutions of the earlier labs this lab uses, so that a mistake there does not "
                "count twice.\n";
    if (!result.counted)
        text += "Not counted: the lab's other run (" + std::string(result.cascade ? "with your own earlier labs" :
                "with the earlier labs' solutions") + ") has more points.\n";
    if (!result.difference.empty()) text += "Where: " + result.difference + "\n";
    if (result.hasHint()) {
        text += "\nHint (a suggestion, not a verdict): this image looks like the known mistake '" + result.hintMistake +
                "': " + result.hint + "\n";
        if (!result.hintDocs.empty()) text += "Read " + result.hintDocs + "\n";
    }
    if ((result.status == GradeStatus::Error || result.status == GradeStatus::NotAttempted) &&
        !result.programOutput.empty())
        text += "\nThe program's output:\n" + result.programOutput + "\n";
    return text;
}

} // namespace

std::string resultsJson(const std::vector<GradeResult>& results, const Totals& totals, double executionSeconds,
                        const std::string& output) {
    JsonWriter json;
    json.beginObject();
    json.key("score").value(totals.points);
    json.key("execution_time").value(static_cast<int>(std::ceil(std::max(0.0, executionSeconds))));
    json.key("output").value(output);
    json.key("visibility").value("visible");
    json.key("stdout_visibility").value("hidden");
    json.key("tests").beginArray();
    std::string currentLab;
    int labIndex = 0;
    int caseIndex = 0;
    for (const GradeResult& result : results) {
        if (result.lab != currentLab || labIndex == 0) {
            currentLab = result.lab;
            ++labIndex;
            caseIndex = 0;
        }
        ++caseIndex;
        json.beginObject();
        // A case of a cascade's run that does not count scores 0 of 0, so the
        // tests add up to the top-level score (Cascade.hpp).
        json.key("score").value(result.counted ? result.points : 0.0);
        json.key("max_score").value(result.counted ? result.maxPoints : 0.0);
        // Gradescope's two statuses; stoa-grade's own is in the tags.
        json.key("status").value(result.status == GradeStatus::Passed ? "passed" : "failed");
        json.key("name").value(result.fullName());
        json.key("number").value(testNumber(result.lab, labIndex, caseIndex));
        json.key("output").value(testOutput(result));
        json.key("tags").beginArray().value(result.lab).value(statusName(result.status));
        if (result.cascade) json.value("cascade");
        if (!result.counted) json.value("not counted");
        json.endArray();
        json.key("visibility").value(result.visibility == Visibility::Hidden ? "after_published" : "visible");
        json.key("extra_data").beginObject();
        json.key("render_seconds").value(result.seconds);
        if (result.hasHint()) {
            json.key("hint_mistake").value(result.hintMistake);
            json.key("hint_docs").value(result.hintDocs);
        }
        json.endObject();
        json.endObject();
    }
    json.endArray();
    json.endObject();
    return json.text() + "\n";
}

void writeResultsJson(const std::filesystem::path& path, const std::vector<GradeResult>& results,
                      const Totals& totals, double executionSeconds, const std::string& output) {
    writeReportFile(path, resultsJson(results, totals, executionSeconds, output), "the results");
}

} // namespace stoa::grader
