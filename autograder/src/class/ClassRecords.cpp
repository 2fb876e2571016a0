// What the class report reads: each student's results.json, the gradebook's
// grades, the labs' manifests, a folder of results.json files. Declared in
// ClassReport.hpp.

#include "ClassReport.hpp"

#include "GradeResult.hpp"
#include "ResultsTests.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <algorithm>
#include <sstream>

namespace stoa::grader {

namespace {

constexpr std::size_t kLineLength = 240;   // a compile error or a note in the report

std::string firstLine(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    if (line.size() > kLineLength) line = line.substr(0, kLineLength) + "...";
    return line;
}

// The first line of a build test's output that names an error: the compiler's
// first complaint ("transforms.cpp:12:5: error: ..."), or the first line after
// the test's own heading when none does.
std::string firstErrorLine(const std::string& output) {
    std::istringstream lines(output);
    std::string line;
    std::string fallback;
    bool heading = true;
    while (std::getline(lines, line)) {
        if (heading) {   // "The lab does not compile:"
            heading = false;
            continue;
        }
        if (fallback.empty() && !line.empty()) fallback = line;
        if (line.find("error") != std::string::npos) return firstLine(line);
    }
    return firstLine(fallback);
}

// "timed out after 15 s ...", "too slow: ...", "not run: after a first timeout ..."
// (CaseRunner.cpp, Grader.cpp): the test's first output line is "<status>: <reason>".
bool reasonIsTimeout(const std::string& output) {
    std::string line = output.substr(0, output.find('\n'));
    return line.find("timed out") != std::string::npos || line.find("too slow") != std::string::npos ||
           line.find("after a first timeout") != std::string::npos;
}

// The hint's text from a test's output: "... the known mistake 'NAME': HINT".
std::string hintText(const std::string& output, const std::string& mistake) {
    const std::string marker = "the known mistake '" + mistake + "': ";
    std::size_t at = output.find(marker);
    if (at == std::string::npos) return "";
    at += marker.size();
    return output.substr(at, output.find('\n', at) - at);
}

CaseRecord caseRecordOf(const JsonValue& test) {
    CaseRecord record;
    record.name = caseOfTest(test);
    record.status = testStatus(test);
    std::string output = stringMember(test, "output");
    record.timedOut = reasonIsTimeout(output);
    if (const JsonValue* extra = test.find("extra_data")) {
        record.hintMistake = stringMember(*extra, "hint_mistake");
        record.hintDocs = stringMember(*extra, "hint_docs");
        if (!record.hintMistake.empty()) record.hint = hintText(output, record.hintMistake);
    }
    return record;
}

} // namespace

bool LabRecord::notAttempted() const {
    if (cases.empty()) return false;
    const std::string notAttemptedName = statusName(GradeStatus::NotAttempted);
    return std::all_of(cases.begin(), cases.end(),
                       [&](const CaseRecord& record) { return record.status == notAttemptedName; });
}

std::vector<std::string> LabRecord::timedOutCases() const {
    std::vector<std::string> names;
    for (const CaseRecord& record : cases)
        if (record.timedOut) names.push_back(record.name);
    return names;
}

StudentRecord readStudentResults(const std::filesystem::path& resultsJson, const std::string& student) {
    JsonValue document = readJsonFile(resultsJson);
    if (!document.isObject())
        throw InputError(resultsJson.string(), 0, "not a results.json: expected an object with \"score\" and \"tests\"");
    StudentRecord record;
    record.student = student;
    record.status = "graded";
    const JsonValue* tests = document.find("tests");
    if (tests && !tests->isArray()) throw InputError(resultsJson.string(), 0, "\"tests\" is not an array");
    if (!tests || tests->items().empty()) {
        if (!document.find("score") && !document.find("output"))
            throw InputError(resultsJson.string(), 0, "not a results.json: no \"tests\", \"score\" or \"output\"");
        record.status = "not graded";
        record.note = firstLine(stringMember(document, "output"));
        return record;
    }
    for (const JsonValue& test : tests->items()) {
        if (!test.isObject()) throw InputError(resultsJson.string(), 0, "a test that is not an object");
        std::string lab = labOfTest(test);
        if (lab.empty()) continue;   // a test another autograder added
        LabRecord& labRecord = record.labs[lab];
        labRecord.points += numberMember(test, "score");
        labRecord.maxPoints += numberMember(test, "max_score");
        if (caseOfTest(test) == "build") {
            // A lab graded through its cascade program has its points in its
            // cases and a build test worth 0 (ClassResults.cpp).
            if (numberMember(test, "max_score") > 0.0) {
                labRecord.doesNotCompile = true;
                labRecord.compileError = firstErrorLine(stringMember(test, "output"));
            }
            continue;
        }
        if (hasTag(test, "not counted")) continue;
        labRecord.cases.push_back(caseRecordOf(test));
    }
    for (const auto& entry : record.labs) {
        record.points += entry.second.points;
        record.maxPoints += entry.second.maxPoints;
    }
    return record;
}

StudentRecord recordOfGrade(const StudentGrade& grade, const std::filesystem::path& outDir) {
    StudentRecord record;
    std::filesystem::path studentDir = outDir / grade.student;
    std::error_code error;
    if (std::filesystem::is_regular_file(studentDir / "results.json", error)) {
        try {
            record = readStudentResults(studentDir / "results.json", grade.student);
        } catch (const std::exception&) {
            record = StudentRecord{};   // the gradebook's figures still stand
        }
    }
    record.student = grade.student;
    record.status = grade.status;
    record.note.clear();
    if (grade.status != "graded" && grade.status != "partly built" && grade.status != "build failed")
        for (const std::string& note : grade.notes) record.note += (record.note.empty() ? "" : "; ") + note;
    record.points = grade.points;
    record.maxPoints = grade.maxPoints;
    for (const auto& [lab, labGrade] : grade.labs) {
        LabRecord& labRecord = record.labs[lab];
        labRecord.points = labGrade.points;
        labRecord.maxPoints = labGrade.maxPoints;
        labRecord.doesNotCompile = !labGrade.built && !labGrade.cascadeBuilt && grade.status != "configure failed" &&
                                   grade.status != "no labs/ folder" && grade.status != "grader error";
        const std::string prefix = "does not compile: ";
        if (labRecord.doesNotCompile && labGrade.note.rfind(prefix, 0) == 0)
            labRecord.compileError = labGrade.note.substr(prefix.size());
        if (!labRecord.doesNotCompile) labRecord.compileError.clear();
    }
    if (std::filesystem::is_regular_file(studentDir / "report.html", error))
        record.reportLink = grade.student + "/report.html";
    return record;
}

LabCases readLabCases(const std::filesystem::path& sourceDir, const std::string& lab) {
    LabCases cases;
    cases.lab = lab;
    for (const std::filesystem::path& manifest :
         {sourceDir / "labs" / lab / "cases.ini", sourceDir / "solutions" / lab / "hidden_cases.ini"}) {
        std::error_code error;
        if (!std::filesystem::is_regular_file(manifest, error)) continue;
        for (const CaseSpec& spec : loadManifest(manifest).cases) {
            cases.order.push_back(spec.name);
            cases.descriptions[spec.name] = spec.description;
            if (!spec.check.empty()) cases.checks.insert(spec.name);
            cases.maxPoints += spec.points;
        }
    }
    return cases;
}

ClassSummary summarizeGrades(const std::vector<StudentGrade>& grades, const Framework& framework,
                             const std::filesystem::path& outDir) {
    std::vector<StudentRecord> records;
    for (const StudentGrade& grade : grades) records.push_back(recordOfGrade(grade, outDir));
    std::vector<LabCases> labs;
    for (const std::string& lab : framework.labs) {
        labs.push_back(readLabCases(framework.sourceDir, lab));   // read before, by locateFramework()
        labs.back().maxPoints = framework.labMaxPoints.at(lab);
    }
    return summarizeClass(std::move(records), std::move(labs), "stoa-grade-class");
}

std::vector<StudentRecord> readResultsFolder(const std::filesystem::path& folder, std::vector<std::string>& unreadable) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        throw InputError(folder.string(), 0, "not a folder; --report-from expects a folder of results.json files "
                                             "(STUDENT/results.json or STUDENT.json)");
    std::vector<std::pair<std::string, std::filesystem::path>> found;   // student, file
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        std::string name = entry.path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        if (entry.is_directory(error)) {
            if (std::filesystem::exists(entry.path() / "results.json", error))
                found.emplace_back(name, entry.path() / "results.json");
            else if (std::filesystem::exists(entry.path() / "submission-files.txt", error))   // stoa-grade-class's
                unreadable.push_back((entry.path() / "results.json").string() + ": none; nothing was graded "
                                     "(the student's line in gradebook.csv says why)");
        } else if (entry.path().extension() == ".json" && name != "class.json") {
            found.emplace_back(entry.path().stem().string(), entry.path());
        }
    }
    if (error) throw InputError(folder.string(), 0, "cannot list the folder: " + error.message());
    std::sort(found.begin(), found.end());
    std::vector<StudentRecord> records;
    for (const auto& [student, path] : found) {
        try {
            StudentRecord record = readStudentResults(path, student);
            if (std::filesystem::is_regular_file(path.parent_path() / "report.html", error) &&
                path.filename() == "results.json")
                record.reportLink = student + "/report.html";
            records.push_back(std::move(record));
        } catch (const std::exception& failure) {
            unreadable.push_back(failure.what());
        }
    }
    if (found.empty())
        throw InputError(folder.string(), 0, "no results here: expected STUDENT/results.json or STUDENT.json files");
    return records;
}

} // namespace stoa::grader
