// What a student's results.json says, read back into their grade; the
// "<lab>/build" tests of the labs that did not compile, added to it; and the
// class's gradebook. Declared in ClassGrader.hpp.

#include "ClassGrader.hpp"

#include "BatchGradeJson.hpp"
#include "GradeResult.hpp"
#include "JsonWriter.hpp"
#include "Report.hpp"
#include "ReportFile.hpp"
#include "ResultsTests.hpp"

#include <stoa/core/InputError.hpp>

#include <sstream>

namespace stoa::grader {

namespace {

std::string describeCounts(const std::map<std::string, int>& counts, int total) {
    const std::string passed = statusName(GradeStatus::Passed);
    const std::string notAttempted = statusName(GradeStatus::NotAttempted);
    if (counts.count(passed) && counts.at(passed) == total) return "";
    if (counts.count(notAttempted) && counts.at(notAttempted) == total) return notAttempted;
    std::string text;
    for (const auto& [status, count] : counts)
        if (status != passed) text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + status;
    return text;
}

// results.json's output once the "<lab>/build" tests are in: the score line
// (stoa-grade's "score: X / Y (20 passed)", none when nothing was graded) with
// the total of every test, so that a lab that did not compile counts with its
// points, and one line per lab that did not compile after the rest.
std::string outputWithBuildFailures(const std::string& output, double points, double maxPoints,
                                    const StudentGrade& grade, const std::map<std::string, std::string>& messages) {
    std::istringstream lines(output);
    std::string line;
    std::string counts;
    std::string rest;
    bool scoreLineSeen = false;
    while (std::getline(lines, line)) {
        if (!scoreLineSeen && line.rfind("score: ", 0) == 0) {
            scoreLineSeen = true;
            std::size_t open = line.find(" (");
            if (open != std::string::npos && line.back() == ')') counts = line.substr(open + 2, line.size() - open - 3);
            continue;
        }
        rest += line + "\n";
    }
    int notGraded = 0;   // a lab graded through its cascade program has its cases in the counts
    for (const auto& entry : messages)
        if (!grade.labs.at(entry.first).cascadeBuilt) ++notGraded;
    if (notGraded > 0)
        counts += (counts.empty() ? "" : ", ") + std::to_string(notGraded) +
                  (notGraded == 1 ? " lab does not compile" : " labs do not compile");
    std::string text = "score: " + formatPoints(points) + " / " + formatPoints(maxPoints) +
                       (counts.empty() ? "" : " (" + counts + ")") + "\n" + rest;
    for (const auto& entry : messages) text += "lab " + entry.first + " does not compile (see its test)\n";
    return text;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

} // namespace

void addBuildFailures(const std::filesystem::path& resultsJson, const StudentGrade& grade,
                      const std::map<std::string, std::string>& messages) {
    JsonValue document = JsonValue::object();
    std::error_code error;
    if (std::filesystem::exists(resultsJson, error)) document = readJsonFile(resultsJson);
    JsonValue tests = JsonValue::array();
    if (const JsonValue* existing = document.find("tests")) tests = *existing;
    for (const auto& [lab, message] : messages) {
        JsonValue test = JsonValue::object();
        test.set("score", JsonValue::number(0));
        // A lab graded through its cascade program already has its points in the tests.
        const LabGrade& labGrade = grade.labs.at(lab);
        test.set("max_score", JsonValue::number(labGrade.cascadeBuilt ? 0.0 : labGrade.maxPoints));
        test.set("status", JsonValue::string("failed"));   // Gradescope's word, not a GradeStatus
        test.set("name", JsonValue::string(lab + "/build"));
        test.set("output", JsonValue::string(
            (labGrade.cascadeBuilt ? "The lab does not compile with your earlier labs; it was graded with their "
                                     "solutions instead (see its [cascade] tests):\n"
                                   : "The lab does not compile:\n") + message));
        JsonValue tags = JsonValue::array();
        tags.push(JsonValue::string(lab));
        test.set("tags", tags);
        test.set("visibility", JsonValue::string("visible"));
        tests.push(test);
    }
    double score = 0.0;
    double maxScore = 0.0;
    for (const JsonValue& test : tests.items()) {
        if (const JsonValue* points = test.find("score")) score += points->asNumber();
        if (const JsonValue* max = test.find("max_score")) maxScore += max->asNumber();
    }
    document.set("score", JsonValue::number(score));
    const JsonValue* output = document.find("output");
    document.set("output", JsonValue::string(
        outputWithBuildFailures(output ? output->asString() : "", score, maxScore, grade, messages)));
    document.set("tests", tests);
    writeReportFile(resultsJson, document.dump() + "\n", "the results");
}

void addResults(const std::filesystem::path& resultsJson, StudentGrade& grade) {
    JsonValue document = readJsonFile(resultsJson);
    const JsonValue* tests = document.find("tests");
    if (!tests || !tests->isArray()) throw InputError(resultsJson.string(), 0, "no \"tests\" array");
    std::map<std::string, std::map<std::string, int>> counts;
    std::map<std::string, int> totals;
    std::map<std::string, LabGrade> sums;
    for (const JsonValue& test : tests->items()) {
        std::string lab = labOfTest(test);
        if (grade.labs.find(lab) == grade.labs.end()) continue;
        LabGrade& sum = sums[lab];
        if (const JsonValue* score = test.find("score")) sum.points += score->asNumber();
        if (const JsonValue* max = test.find("max_score")) sum.maxPoints += max->asNumber();
        if (hasTag(test, "not counted")) continue;   // the lab's other run counts (Cascade.hpp)
        ++counts[lab][testStatus(test)];
        ++totals[lab];
    }
    for (const auto& [lab, sum] : sums) {
        LabGrade& labGrade = grade.labs[lab];
        labGrade.points = sum.points;
        labGrade.maxPoints = sum.maxPoints;
        labGrade.note = describeCounts(counts[lab], totals[lab]);
        if (!labGrade.built && labGrade.cascadeBuilt)
            labGrade.note = "does not compile with your earlier labs; graded with their solutions" +
                            (labGrade.note.empty() ? "" : ": " + labGrade.note);
    }
}

std::string gradebookCsv(const std::vector<std::string>& labs, const std::vector<StudentGrade>& grades) {
    std::ostringstream csv;
    csv << "student";
    for (const std::string& lab : labs) csv << "," << csvField(lab);
    csv << ",total,max,status,notes\n";
    for (const StudentGrade& grade : grades) {
        csv << csvField(grade.student);
        for (const std::string& lab : labs) {
            auto found = grade.labs.find(lab);
            csv << "," << formatPoints(found == grade.labs.end() ? 0.0 : found->second.points);
        }
        std::string notes;
        for (const std::string& note : grade.notes) notes += (notes.empty() ? "" : "; ") + note;
        csv << "," << formatPoints(grade.points) << "," << formatPoints(grade.maxPoints) << ","
            << csvField(grade.status) << "," << csvField(notes) << "\n";
    }
    return csv.str();
}

} // namespace stoa::grader
