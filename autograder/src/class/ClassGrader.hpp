#pragma once
// stoa-grade-class: grades a folder of submissions against a prebuilt framework.
//
// First every submission is staged: its files' hashes recorded, then copied (or
// unpacked) into <out>/<student>/submission, before any student's code runs.
// Then for each student, on up to `jobs` students at once, from the staged copy
// (each step confined to that student's files and the framework, FileSandbox.hpp):
//   1. configure cmake -S autograder/submission -B <out>/<student>/build
//                      -DStoa_DIR=<framework build>/stoa-config -DSTOA_TRACK_DIR=<its labs/>
//                (only the student files each lab declares are taken from it);
//   2. build     the earlier labs' solutions the cascades link (NN_name-cascade-solutions),
//                where solutions/ may be read; then one lab at a time, where it may
//                not, so a compile error fails that lab (and the labs that use its
//                code) with the compiler's message, not the batch;
//   3. grade     the framework's stoa-grade on the student's programs: results.json
//                (and report.html where stoa-grade has --html) in <out>/<student>/.
// Then every submission's files are hashed again (a change is noted: it must never
// happen), and <out>/gradebook.csv gets one row per student with points per lab,
// total, max, status and notes; <out>/class.html and class.json sum up the class
// (ClassReport.hpp), and with --similarity <out>/similarity.html ranks the pairs
// of submissions that look alike (Similarity.hpp).

#include "BatchGradeSubmissions.hpp"
#include "FileSandbox.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace stoa::grader {

struct ClassOptions {
    std::filesystem::path submissionsDir;
    std::filesystem::path outDir;
    int jobs = 1;                          // students built and graded at once
    std::vector<std::string> labs;         // --lab; empty = every lab
    double timeoutSeconds = 0.0;           // per case, passed to stoa-grade; 0: stoa-grade's own (RenderTimes.hpp)
    std::filesystem::path frameworkBuild;  // empty = the build folder stoa-grade-class runs from
    bool similarity = false;               // --similarity: also compare the submissions (Similarity.hpp)
    bool similarityOnly = false;           // --similarity-only: stage and compare, build and grade nothing
};

/// The prebuilt framework the submissions compile against.
struct Framework {
    std::filesystem::path sourceDir;       // the Stoa tree: labs/, autograder/submission/
    std::filesystem::path buildDir;        // its build: stoa-config/, bin/stoa-grade
    std::filesystem::path gradeProgram;    // <build>/bin/stoa-grade
    std::filesystem::path cmake;           // the cmake that configured it
    bool gradeWritesHtml = false;          // stoa-grade --help mentions --html
    std::vector<std::string> labs;         // the labs to grade, in order
    std::map<std::string, double> labMaxPoints;   // from the manifests (public and hidden)
};

/// Checks that `buildDir` holds a built framework (stoa-config/StoaConfig.cmake,
/// bin/stoa-grade) and reads the labs of `sourceDir`. Throws InputError saying
/// what to build when something is missing, UsageError for an unknown --lab.
Framework locateFramework(const std::filesystem::path& sourceDir, const std::filesystem::path& buildDir,
                          const std::vector<std::string>& requestedLabs, const std::filesystem::path& cmake);

struct LabGrade {
    double points = 0.0;
    double maxPoints = 0.0;
    bool built = false;
    bool cascadeBuilt = false;             // its cascade program built (earlier labs' solutions linked in)
    std::string note;                      // "not attempted", "2 failed", "does not compile: ..."
};

struct StudentGrade {
    std::string student;
    std::map<std::string, LabGrade> labs;
    double points = 0.0;
    double maxPoints = 0.0;
    std::string status;                    // "graded", "build failed", "no labs/ folder", ...
    std::vector<std::string> notes;
};

/// A submission staged before any student's code is built or run: its copy's
/// labs/ folder, or why there is none, and the record of its input files.
struct StagedSubmission {
    Submission submission;
    std::filesystem::path labsDir;         // in <outDir>/<student>/submission; empty when staging failed
    std::string error;                     // why it could not be staged
    std::vector<InputFile> inputs;         // recorded before staging (<outDir>/<student>/submission-files.txt)
};

/// Records the submission's input files and copies (or unpacks) it into
/// <outDir>/<student>/submission. Never throws.
StagedSubmission stageForGrading(const Submission& submission, const ClassOptions& options);

/// Builds and grades one staged submission in <outDir>/<student>/, each step
/// confined to the student's own files and the framework (buildAccess()). Never
/// throws: every failure becomes the student's status and notes. `progress` gets
/// one-line updates ("building...", "grading...").
StudentGrade gradeSubmission(const StagedSubmission& staged, const Framework& framework, const ClassOptions& options,
                             const std::function<void(const std::string&)>& progress);

/// What a step of a student's build may touch: the system, the framework's tree
/// and build (without the submissions, the grades folder and, unless
/// `readSolutions`, solutions/), the student's build folder (to write), and for
/// the configure step (`stagedLabs` not empty) the student's staged files.
FileAccess buildAccess(const Framework& framework, const ClassOptions& options, const std::filesystem::path& studentDir,
                       bool readSolutions, const std::filesystem::path& stagedLabs = {});

/// Points per lab and overall from a results.json as stoa-grade writes it
/// (tests named "<lab>/<case>" or tagged with the lab). Throws InputError when it does not parse.
void addResults(const std::filesystem::path& resultsJson, StudentGrade& grade);

/// Adds a failed "<lab>/build" test with the compiler's message for each lab in
/// `messages` (lab -> message) to the results.json at `resultsJson`, creating it
/// when nothing was graded. A lab graded through its cascade program gets a test
/// worth 0 (its cases carry its points). The document's "score" and the score line
/// of its "output" ("score: X / Y (...)") then count every test, so the total
/// includes the points of a lab that did not compile. `grade` names each lab's points.
void addBuildFailures(const std::filesystem::path& resultsJson, const StudentGrade& grade,
                      const std::map<std::string, std::string>& messages);

/// The gradebook as CSV text: student, one column per lab, total, max, status, notes.
std::string gradebookCsv(const std::vector<std::string>& labs, const std::vector<StudentGrade>& grades);

/// The whole batch; returns the exit status (0 when the batch ran, whatever the grades).
int runClassGrade(const ClassOptions& options, const Framework& framework, std::ostream& out, std::ostream& err);

} // namespace stoa::grader
