// stoa-grade-class: grades a folder of submissions into a gradebook (see ClassGrader.hpp).
//
//   stoa-grade-class SUBMISSIONS_DIR --out DIR [--jobs N] [--lab NN]... [--timeout SECONDS]
//                    [--framework-build DIR] [--similarity | --similarity-only]
//   stoa-grade-class --report-from FOLDER [--out DIR]

#include "ChildProcess.hpp"
#include "ClassGrader.hpp"
#include "ClassReport.hpp"
#include "CommandLine.hpp"
#include "LabCatalog.hpp"

#include <stoa/core/Paths.hpp>

#include <cstdlib>
#include <iostream>
#include <thread>

namespace {

const char* const kUsage = R"(stoa-grade-class: grades a folder of submissions into a gradebook.

usage:
  stoa-grade-class SUBMISSIONS_DIR --out DIR [--jobs N] [--lab NN]... [--timeout SECONDS]
                   [--framework-build DIR] [--similarity | --similarity-only]
  stoa-grade-class --report-from FOLDER [--out DIR]

SUBMISSIONS_DIR holds one entry per student: a folder, a .zip or a .tar.gz of the
student's labs/ tree (labs/ at the top, or inside one top folder). The student's
name is the entry's name. Only the student files of each lab are compiled, against
the framework this program was built with.

options:
  --out DIR               where gradebook.csv and one folder per student go
  --jobs N                students built and graded at once (default: the number of cores)
  --lab NN_name|NN        grade only this lab (repeatable)
  --timeout SECONDS       wall-clock limit per case (default: stoa-grade's, from the
                          solution's recorded render time of each case)
  --framework-build DIR   the framework's build folder (default: the one this program is in)
  --similarity            also rank the pairs of submissions that look alike, lab by lab
                          (Debian's similarity-tester: sim_c, sim_text), into DIR/similarity.html
  --similarity-only       stage the submissions and compare them; build and grade nothing
  --report-from FOLDER    no grading: the class report from a folder of results.json files
                          (FOLDER/STUDENT/results.json or FOLDER/STUDENT.json, e.g. a Gradescope
                          export or an earlier --out folder), into --out (default: FOLDER)

output: DIR/gradebook.csv (student, points per lab, total, max, status, notes),
DIR/class.html and DIR/class.json (what the class got wrong, the score
distributions), and DIR/STUDENT/ with results.json, report.html (where stoa-grade
writes HTML) and the configure, build and grade logs. Exit status 0 when the batch ran, 1 when it could
not start, 2 on bad usage.
)";

int parseJobs(const std::string& text) {
    char* end = nullptr;
    long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < 1 || value > 256)
        throw stoa::grader::UsageError("--jobs expects a whole number from 1 to 256, got '" + text + "'");
    return static_cast<int>(value);
}

} // namespace

int main(int argc, char** argv) {
    using namespace stoa::grader;
    try {
        ClassOptions options;
        std::filesystem::path reportFrom;
        options.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        for (int i = 1; i < argc; ++i) {
            std::string argument = argv[i];
            auto value = [&](const char* what) -> std::string {
                if (i + 1 >= argc) throw UsageError(argument + " needs " + what);
                return argv[++i];
            };
            if (argument == "--help" || argument == "-h") {
                std::cout << kUsage;
                return 0;
            } else if (argument == "--out") {
                options.outDir = value("a folder for the gradebook");
            } else if (argument == "--jobs") {
                options.jobs = parseJobs(value("a number of students"));
            } else if (argument == "--lab") {
                options.labs.push_back(value("a lab, such as 01_transforms or 01"));
            } else if (argument == "--timeout") {
                std::string text = value("a number of seconds");
                char* end = nullptr;
                options.timeoutSeconds = std::strtod(text.c_str(), &end);
                if (text.empty() || *end != '\0' || !(options.timeoutSeconds > 0))
                    throw UsageError("--timeout expects a positive number of seconds, got '" + text + "'");
            } else if (argument == "--framework-build") {
                options.frameworkBuild = value("the framework's build folder");
            } else if (argument == "--similarity") {
                options.similarity = true;
            } else if (argument == "--similarity-only") {
                options.similarityOnly = true;
            } else if (argument == "--report-from") {
                reportFrom = value("a folder of results.json files");
            } else if (argument.rfind("-", 0) == 0) {
                throw UsageError("unknown option '" + argument +
                                 "'; the options are --out, --jobs, --lab, --timeout, --framework-build, "
                                 "--similarity, --similarity-only, --report-from, --help");
            } else if (options.submissionsDir.empty()) {
                options.submissionsDir = argument;
            } else {
                throw UsageError("one folder of submissions, please: got '" + options.submissionsDir.string() +
                                 "' and '" + argument + "'");
            }
        }
        if (!reportFrom.empty()) {
            if (!options.submissionsDir.empty() || options.similarity || options.similarityOnly)
                throw UsageError("--report-from grades nothing: give it a folder of results.json files and --out only");
            return runReportFrom(reportFrom, options.outDir.empty() ? reportFrom : options.outDir,
                                 stoa::paths::sourceDir(), std::cout, std::cerr);
        }
        if (options.similarity && options.similarityOnly)
            throw UsageError("--similarity grades and compares, --similarity-only only compares: choose one");
        if (options.submissionsDir.empty()) throw UsageError("which folder of submissions? stoa-grade-class DIR --out OUT");
        if (options.outDir.empty()) throw UsageError("--out DIR is required (where the gradebook goes)");

        killChildrenOnInterrupt();
        std::filesystem::path build = options.frameworkBuild;
        if (build.empty()) build = executableDir().parent_path();
        Framework framework = locateFramework(stoa::paths::sourceDir(), build, options.labs, STOA_CMAKE_COMMAND);
        return runClassGrade(options, framework, std::cout, std::cerr);
    } catch (const UsageError& error) {
        std::cerr << "stoa-grade-class: " << error.what() << "\n(run stoa-grade-class --help for the usage)\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "stoa-grade-class: " << error.what() << "\n";
        return 1;
    }
}
