#pragma once
// The instructor's view of a class: what the class got wrong, written beside
// the gradebook by every stoa-grade-class run, and by `--report-from FOLDER`
// from a folder of results.json files (a Gradescope export):
//
//   <out>/class.html   one static page, no scripts, nothing loaded from elsewhere:
//                      what to teach again first (the cases most students got
//                      wrong, the gallery mistakes hints named, the property
//                      checks that failed most), the score distributions per lab
//                      and overall as inline SVG histograms, each case's pass
//                      rate, and the students whose lab did not compile, timed
//                      out or was not attempted, with links to their reports
//   <out>/class.json   the same figures for scripts
//
// Everything comes from each student's results.json (ResultsTests.hpp reads its
// tests); a stoa-grade-class run takes the points from its gradebook, so that
// class.json and gradebook.csv agree to the digit. Student-controlled text
// (names, file names, compiler messages, a forged results.json) is escaped.

#include "ClassGrader.hpp"

#include <array>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace stoa::grader {

/// One counted case of a student's lab (a lab's run that does not count is left out).
struct CaseRecord {
    std::string name;           // "orbit_front"
    std::string status;         // statusName(): "passed", "failed", "not attempted", "error", "no reference"
    bool timedOut = false;      // it ran out of time, or was not run after timeouts
    std::string hintMistake;    // the gallery mistake its hint named; "" when none
    std::string hint;           // that mistake's hint, as the student read it
    std::string hintDocs;       // "docs/labs/02_shading.md#the-half-vector"
};

struct LabRecord {
    double points = 0.0;
    double maxPoints = 0.0;
    bool doesNotCompile = false;   // not built, not even with the earlier labs' solutions
    std::string compileError;      // its first error line
    std::vector<CaseRecord> cases; // the counted run's cases, in results.json order

    /// Some case, and every case, "not attempted".
    bool notAttempted() const;
    /// The cases that ran out of time.
    std::vector<std::string> timedOutCases() const;
};

struct StudentRecord {
    std::string student;
    std::string status;            // the gradebook's ("graded", "build failed", ...); "graded" from results.json alone
    std::string note;              // why nothing was graded, when nothing was
    double points = 0.0;
    double maxPoints = 0.0;
    std::map<std::string, LabRecord> labs;
    std::string reportLink;        // "alice/report.html" relative to class.html; "" when there is none
};

/// Reads a results.json as stoa-grade and stoa-grade-class write it. A document
/// without tests (a submission that could not be graded) gives a record without
/// labs whose note is its output's first line. Throws InputError naming the file
/// when it does not parse or is not a results.json.
StudentRecord readStudentResults(const std::filesystem::path& resultsJson, const std::string& student);

/// The record of a student graded by this run: points, status and compile errors
/// from the gradebook's `grade`, cases from <outDir>/<student>/results.json where
/// it exists and parses. Never throws.
StudentRecord recordOfGrade(const StudentGrade& grade, const std::filesystem::path& outDir);

/// What the report knows of a lab besides the students' results: its cases from
/// the manifests (public and hidden), in file order.
struct LabCases {
    std::string lab;
    double maxPoints = 0.0;                        // 0: the largest any student's results name
    std::vector<std::string> order;                // case names in manifest order
    std::map<std::string, std::string> descriptions;
    std::set<std::string> checks;                  // the property checks (cases.ini `check`)
};

/// The lab's cases from <sourceDir>/labs/<lab>/cases.ini and
/// <sourceDir>/solutions/<lab>/hidden_cases.ini; a lab this tree lacks gets none
/// (its cases then come from the results alone).
LabCases readLabCases(const std::filesystem::path& sourceDir, const std::string& lab);

/// How the class's scores of one lab (or overall) are spread.
struct ScoreDistribution {
    static constexpr int kBins = 11;   // 0-9%, 10-19%, ..., 90-99%, and full marks on its own
    double maxPoints = 0.0;
    double mean = 0.0;                 // points
    double median = 0.0;               // points
    std::array<int, kBins> bins{};
};

/// The distribution of `points` out of `maxPoints` each.
ScoreDistribution distributionOf(const std::vector<double>& points, double maxPoints);

/// One case across the class: how many students' counted run had each status.
struct CaseSummary {
    std::string name;
    std::string description;
    bool propertyCheck = false;
    int passed = 0;
    int failed = 0;         // a wrong picture, or a check that does not hold
    int notAttempted = 0;
    int error = 0;          // crashed, timed out, no reference
    int missing = 0;        // no result: the lab did not compile, or the submission had no labs
    double passRate(int students) const { return students > 0 ? double(passed) / students : 0.0; }
};

struct MistakeSummary {
    std::string name;
    std::string hint;
    std::string docs;
    std::vector<std::string> students;   // sorted
    std::vector<std::string> cases;      // the cases its hint was given on
};

struct StudentProblem {
    std::string student;
    std::string detail;     // the first compile error, the cases that timed out
};

struct LabSummary {
    std::string lab;
    ScoreDistribution scores;
    std::vector<CaseSummary> cases;               // by pass rate, lowest first
    std::vector<MistakeSummary> mistakes;         // by students, most first
    std::vector<StudentProblem> notCompiled;
    std::vector<StudentProblem> timedOut;
    std::vector<std::string> notAttempted;
};

/// One line of "what to teach again": a case, a mistake or a check, and how many it cost.
struct TeachingPoint {
    std::string kind;       // "mistake", "case", "check", "compile"
    std::string lab;
    std::string name;       // the mistake, case or check
    std::string text;       // the hint, the case's description, the first compile error
    std::string docs;
    std::vector<std::string> students;
};

struct ClassSummary {
    std::string source;                       // "stoa-grade-class" or the --report-from folder
    std::vector<StudentRecord> students;      // in gradebook order
    std::vector<LabSummary> labs;             // in lab order
    ScoreDistribution overall;
    std::vector<TeachingPoint> teachAgain;    // most students first
    std::vector<StudentProblem> notGraded;    // submissions with nothing graded (no labs/, configure failed, ...)
    std::vector<std::string> unreadable;      // "FILE: why" for results that could not be read
};

/// Sums up the class. `labs` names the labs in order with their cases; a lab no
/// entry names is added from the results, after them.
ClassSummary summarizeClass(std::vector<StudentRecord> students, std::vector<LabCases> labs, const std::string& source);

/// The summary of this run's grades (summarizeClass() over recordOfGrade() of
/// each), with the labs' cases from the framework's manifests.
ClassSummary summarizeGrades(const std::vector<StudentGrade>& grades, const Framework& framework,
                             const std::filesystem::path& outDir);

/// class.json: the summary's figures (see docs/instructor-guide.md, "The class report").
std::string classJson(const ClassSummary& summary);

/// class.html: the page (ClassReportHtml.cpp).
std::string classHtml(const ClassSummary& summary);

/// Writes <outDir>/class.html and <outDir>/class.json. Throws InputError when it cannot.
void writeClassReport(const std::filesystem::path& outDir, const ClassSummary& summary);

/// The records of a folder of results.json files, for --report-from: each
/// STUDENT/results.json (stoa-grade-class's --out folder, or one folder per
/// student) and each STUDENT.json beside them. A file that cannot be read is
/// named in `unreadable` and left out. Throws InputError when `folder` is not a
/// folder or holds no results.
std::vector<StudentRecord> readResultsFolder(const std::filesystem::path& folder, std::vector<std::string>& unreadable);

/// --report-from: reads `folder`, writes class.html and class.json into `outDir`,
/// says what it wrote on `out` and what it left out on `err`. Returns the exit
/// status: 0 when the report was written, 1 when there was nothing to report.
int runReportFrom(const std::filesystem::path& folder, const std::filesystem::path& outDir,
                  const std::filesystem::path& sourceDir, std::ostream& out, std::ostream& err);

} // namespace stoa::grader
