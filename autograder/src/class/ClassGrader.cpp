#include "ClassGrader.hpp"

#include "BatchGradeJson.hpp"
#include "ChildProcess.hpp"
#include "ClassReport.hpp"
#include "GradeOptions.hpp"
#include "Grader.hpp"
#include "JsonWriter.hpp"
#include "LabCatalog.hpp"
#include "LabSandbox.hpp"
#include "RenderTimes.hpp"
#include "Similarity.hpp"
#include "Report.hpp"
#include "ReportFile.hpp"
#include "StrayProcesses.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <mutex>
#include <sstream>

namespace stoa::grader {

namespace {

constexpr std::size_t kNoteLength = 200;       // one note in the gradebook
constexpr std::size_t kMessageLength = 2000;   // the compiler's message in results.json
constexpr std::uintmax_t kMaxSeededShaderCacheBytes = 64ull << 20;   // a larger user cache is not copied

// Builds run the student's code through the compiler only; a wall clock is
// enough. `files` is what the step may touch; its temporary files go in
// <build>/tmp (`buildDir` empty: the grader's TMPDIR).
ProcessLimits buildLimits(std::size_t outputBytes, const FileAccess& files, const std::filesystem::path& buildDir) {
    ProcessLimits limits;
    limits.files = files;
    if (!buildDir.empty()) limits.environment.push_back("TMPDIR=" + (buildDir / "tmp").string());
    limits.timeoutSeconds = 900.0;
    limits.cpuSeconds = 0;
    limits.addressSpaceBytes = 0;
    limits.fileSizeBytes = 0;
    limits.outputLimitBytes = outputBytes;
    limits.maxProcesses = 0;   // make and the compiler start many; stoa-grade limits the lab programs itself
    limits.maxTasks = 0;
    limits.isolateNetwork = false;
    // The build runs as the user, outside any namespace (a user namespace maps
    // the groups away, which some toolchains' caches mind). What student CMake
    // code starts and leaves running is still killed when each step ends: this
    // program is a child subreaper (StrayProcesses.hpp), and stoa-grade contains
    // the lab programs itself.
    limits.ownPidNamespace = false;
    return limits;
}

// "the build of 01_transforms left 2 processes running (killed)", or "" when it left none.
std::string strayNote(const std::string& step, const ProcessOutcome& outcome) {
    if (outcome.strayProcesses == 0) return "";
    return step + " left " + std::to_string(outcome.strayProcesses) +
           (outcome.strayProcesses == 1 ? " process" : " processes") + " running (killed)";
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string truncated(std::string text, std::size_t length) {
    if (text.size() <= length) return text;
    text.resize(length);
    return text + "...";
}

std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    return text;
}

// The compiler's errors from a build log: the lines that say "error", with the
// line after each (the source line it quotes); the whole tail when none does.
std::string compilerMessage(const std::string& output) {
    std::istringstream lines(output);
    std::string line;
    std::string message;
    int take = 0;
    while (std::getline(lines, line)) {
        bool isError = line.find("error") != std::string::npos && line.find("make") != 0 &&
                       line.find("gmake") != 0;
        if (isError) take = 2;
        if (take > 0) {
            message += line + "\n";
            --take;
        }
    }
    if (message.empty()) message = output.size() > kMessageLength ? output.substr(output.size() - kMessageLength) : output;
    return truncated(message, kMessageLength);
}

// `text` with every occurrence of `prefix` removed (the staging folder in compiler messages).
std::string withoutPrefix(std::string text, const std::string& prefix) {
    for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at))
        text.erase(at, prefix.size());
    return text;
}

// The first error line, for the gradebook: "transforms.cpp:12:5: error: ..." with the path shortened.
std::string firstError(const std::string& message) {
    std::istringstream lines(message);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.find("error") == std::string::npos) continue;
        std::size_t track = line.find("/track/");
        if (track != std::string::npos) line = line.substr(track + 7);
        // The build's sandbox refused a file: "cameras.cpp:1:10: fatal error: /a/b/c/d/e.cpp:
        // Permission denied" -> "cameras.cpp:1:10: cannot read .../c/d/e.cpp (Permission denied): ...".
        const std::string denied = ": Permission denied";
        std::size_t fatal = line.find("fatal error: ");
        if (fatal != std::string::npos && line.size() > denied.size() &&
            line.compare(line.size() - denied.size(), denied.size(), denied) == 0) {
            std::filesystem::path file = line.substr(fatal + 13, line.size() - denied.size() - fatal - 13);
            std::filesystem::path shown = file.filename();
            for (std::filesystem::path up = file.parent_path(); shown.string().size() < 48 && up.has_filename();
                 up = up.parent_path())
                shown = up.filename() / shown;
            line = line.substr(0, fatal) + "cannot read .../" + shown.string() +
                   " (Permission denied): the grader's build reads only the student's own files and the framework";
        }
        return truncated(oneLine(line), kNoteLength);
    }
    return truncated(oneLine(message), kNoteLength);
}

// The student's own Mesa shader cache (a classmate's lab programs must not be
// able to plant compiled shaders in it), started as a copy of this user's, so
// that the shaders every lab shares are not compiled again for each student.
std::filesystem::path seedShaderCache(const std::filesystem::path& studentDir) {
    std::filesystem::path cache = studentDir / "shader-cache";
    std::error_code error;
    if (std::filesystem::exists(cache, error)) return cache;
    std::filesystem::path user = userShaderCache();
    std::uintmax_t bytes = 0;
    for (auto entry = std::filesystem::recursive_directory_iterator(user, error);
         !error && entry != std::filesystem::recursive_directory_iterator(); entry.increment(error))
        if (entry->is_regular_file(error)) bytes += entry->file_size(error);
    if (!error && bytes > 0 && bytes <= kMaxSeededShaderCacheBytes)
        std::filesystem::copy(user, cache, std::filesystem::copy_options::recursive, error);
    std::filesystem::create_directories(cache, error);
    return cache;
}

double manifestPoints(const std::filesystem::path& manifest) {
    double points = 0.0;
    for (const CaseSpec& spec : loadManifest(manifest).cases) points += spec.points;
    return points;
}

} // namespace

Framework locateFramework(const std::filesystem::path& sourceDir, const std::filesystem::path& buildDir,
                          const std::vector<std::string>& requestedLabs, const std::filesystem::path& cmake) {
    Framework framework;
    framework.sourceDir = std::filesystem::absolute(sourceDir);
    framework.buildDir = std::filesystem::absolute(buildDir);
    framework.gradeProgram = framework.buildDir / "bin" / "stoa-grade";
    framework.cmake = cmake;
    std::filesystem::path config = framework.buildDir / "stoa-config" / "StoaConfig.cmake";
    if (!std::filesystem::is_regular_file(config))
        throw InputError(config.string(), 0,
                         "no exported framework here; configure and build the framework first "
                         "(cmake -S . -B build && cmake --build build), or pass --framework-build");
    if (!isExecutable(framework.gradeProgram))
        throw InputError(framework.gradeProgram.string(), 0, "stoa-grade is not built: cmake --build build --target stoa-grade");
    if (!std::filesystem::is_regular_file(framework.sourceDir / "autograder" / "submission" / "CMakeLists.txt"))
        throw InputError(framework.sourceDir.string(), 0, "not a Stoa tree (no autograder/submission/CMakeLists.txt)");
    if (!isExecutable(framework.cmake))
        throw InputError(framework.cmake.string(), 0, "cmake is not there (it configured the framework)");

    ProcessOutcome help = runProcess({framework.gradeProgram.string(), "--help"}, {}, defaultLimits(30.0));
    framework.gradeWritesHtml = help.output.find("--html") != std::string::npos;

    for (const LabEntry& entry : selectLabs(findLabs(framework.sourceDir), requestedLabs)) {
        framework.labs.push_back(entry.lab);
        double points = manifestPoints(entry.manifestPath);
        std::filesystem::path hidden = framework.sourceDir / "solutions" / entry.lab / "hidden_cases.ini";
        if (std::filesystem::is_regular_file(hidden)) points += manifestPoints(hidden);
        framework.labMaxPoints[entry.lab] = points;
    }
    if (framework.labs.empty())
        throw InputError((framework.sourceDir / "labs").string(), 0, "no labs with a cases.ini to grade");
    return framework;
}

StagedSubmission stageForGrading(const Submission& submission, const ClassOptions& options) {
    StagedSubmission staged;
    staged.submission = submission;
    std::filesystem::path studentDir = std::filesystem::absolute(options.outDir / submission.student);
    try {
        std::filesystem::create_directories(studentDir);
        staged.inputs = recordInputs(submission);
        writeText(studentDir / "submission-files.txt", inputsText(staged.inputs));
        staged.labsDir = stageSubmission(submission, studentDir / "submission");
    } catch (const std::exception& error) {
        staged.labsDir.clear();
        staged.error = truncated(oneLine(error.what()), kNoteLength);
    }
    return staged;
}

FileAccess buildAccess(const Framework& framework, const ClassOptions& options, const std::filesystem::path& studentDir,
                       bool readSolutions, const std::filesystem::path& stagedLabs) {
    FileAccess access = systemFileAccess();
    access.readable.push_back(framework.sourceDir);
    access.readable.push_back(framework.buildDir);
    if (!stagedLabs.empty()) access.readable.push_back(stagedLabs);
    access.writable.push_back(studentDir / "build");
    access.excluded.push_back(std::filesystem::absolute(options.outDir));
    access.excluded.push_back(std::filesystem::absolute(options.submissionsDir));
    if (!readSolutions) access.excluded.push_back(framework.sourceDir / "solutions");
    return access;
}

namespace {

// Builds the earlier labs' solutions for the cascades, then each lab and its
// cascade program on its own; records in `grade` what built and returns the
// compiler's message for each lab that did not.
std::map<std::string, std::string> buildEachLab(const Framework& framework, const ClassOptions& options,
                                                const std::filesystem::path& studentDir, StudentGrade& grade,
                                                const std::function<void(const std::string&)>& progress) {
    const std::filesystem::path buildDir = studentDir / "build";
    // The solutions the cascade programs link, compiled before any of the
    // student's files, where solutions/ may be read; no student file is
    // compiled in this step.
    // A lab without a cascade program has no such target: the step fails at once.
    progress("building the earlier labs' solutions for the cascades...");
    const ProcessLimits solutionsBuild = buildLimits(32768, buildAccess(framework, options, studentDir, true), buildDir);
    std::string solutionsLog;
    for (const std::string& lab : framework.labs) {
        ProcessOutcome solutions = runProcess(
            {framework.cmake.string(), "--build", buildDir.string(), "--target", lab + "-cascade-solutions", "-j", "1"},
            studentDir, solutionsBuild);
        solutionsLog += "== " + lab + "-cascade-solutions: " + solutions.describe() + "\n" + solutions.output;
    }
    writeText(studentDir / "build-solutions.log", solutionsLog);

    const ProcessLimits labBuild = buildLimits(32768, buildAccess(framework, options, studentDir, false), buildDir);
    std::map<std::string, std::string> buildErrors;
    for (const std::string& lab : framework.labs) {
        progress("building " + lab + "...");
        ProcessOutcome build = runProcess(
            {framework.cmake.string(), "--build", buildDir.string(), "--target", lab, "-j", "1"}, studentDir, labBuild);
        writeText(studentDir / ("build-" + lab + ".log"), build.output);
        // The cascade program (Cascade.hpp), where the lab uses earlier labs
        // and solutions exist; a lab without one just has no such target.
        ProcessOutcome cascade = runProcess(
            {framework.cmake.string(), "--build", buildDir.string(), "--target", lab + "-cascade", "-j", "1"},
            studentDir, labBuild);
        for (const std::string& note :
             {strayNote("the build of " + lab, build), strayNote("the cascade build of " + lab, cascade)})
            if (!note.empty()) grade.notes.push_back(note);
        LabGrade& labGrade = grade.labs[lab];
        labGrade.built = build.exitedWith(0);
        labGrade.cascadeBuilt = cascade.exitedWith(0);
        if (!labGrade.built) {
            buildErrors[lab] = withoutPrefix(compilerMessage(build.output), (buildDir / "track").string() + "/");
            labGrade.note = "does not compile: " + firstError(buildErrors[lab]);
        }
    }
    return buildErrors;
}

// stoa-grade's command line for the student's built labs.
std::vector<std::string> gradeArguments(const Framework& framework, const ClassOptions& options,
                                        const std::filesystem::path& studentDir, const std::vector<std::string>& built) {
    std::vector<std::string> argv = {framework.gradeProgram.string(),
                                     "--bin-dir", (studentDir / "build" / "bin").string(),
                                     "--json", (studentDir / "results.json").string(),
                                     "--work-dir", (studentDir / "work").string(),
                                     "--shader-cache", seedShaderCache(studentDir).string(),
                                     "--private", std::filesystem::absolute(options.outDir).string(),
                                     "--private", std::filesystem::absolute(options.submissionsDir).string()};
    if (options.timeoutSeconds > 0.0) {
        argv.push_back("--timeout");
        argv.push_back(std::to_string(options.timeoutSeconds));
    }
    for (const std::string& lab : built) {
        argv.push_back("--lab");
        argv.push_back(lab);
    }
    if (framework.gradeWritesHtml) {
        argv.push_back("--html");
        argv.push_back((studentDir / "report.html").string());
    }
    return argv;
}

} // namespace

StudentGrade gradeSubmission(const StagedSubmission& staged, const Framework& framework, const ClassOptions& options,
                             const std::function<void(const std::string&)>& progress) {
    const Submission& submission = staged.submission;
    StudentGrade grade;
    grade.student = submission.student;
    for (const std::string& lab : framework.labs) grade.labs[lab].maxPoints = framework.labMaxPoints.at(lab);
    auto finish = [&](const std::string& status) {
        grade.status = status;
        grade.points = grade.maxPoints = 0.0;
        for (const std::string& lab : framework.labs) {
            grade.points += grade.labs[lab].points;
            grade.maxPoints += grade.labs[lab].maxPoints;
            if (!grade.labs[lab].note.empty()) grade.notes.push_back(lab + ": " + grade.labs[lab].note);
        }
        return grade;
    };

    std::filesystem::path studentDir = std::filesystem::absolute(options.outDir / submission.student);
    std::filesystem::path buildDir = studentDir / "build";
    try {
        std::filesystem::remove(studentDir / "results.json");
        std::filesystem::remove(studentDir / "report.html");
        if (staged.labsDir.empty()) {
            grade.notes.push_back(staged.error);
            return finish("no labs/ folder");
        }
        const std::filesystem::path& labsDir = staged.labsDir;
        std::filesystem::create_directories(buildDir / "tmp");

        progress("configuring...");
        ProcessOutcome configure = runProcess(
            {framework.cmake.string(), "-S", (framework.sourceDir / "autograder" / "submission").string(), "-B",
             buildDir.string(), "-DStoa_DIR=" + (framework.buildDir / "stoa-config").string(),
             "-DSTOA_TRACK_DIR=" + labsDir.string()},
            studentDir, buildLimits(16384, buildAccess(framework, options, studentDir, false, labsDir), buildDir));
        writeText(studentDir / "configure.log", configure.output);
        if (std::string note = strayNote("configure", configure); !note.empty()) grade.notes.push_back(note);
        if (!configure.exitedWith(0)) {
            grade.notes.push_back("configure failed (" + configure.describe() + "); see configure.log: " +
                                  firstError(compilerMessage(configure.output)));
            return finish("configure failed");
        }

        std::map<std::string, std::string> buildErrors = buildEachLab(framework, options, studentDir, grade, progress);
        std::vector<std::string> built;
        for (const std::string& lab : framework.labs)
            if (grade.labs[lab].built || grade.labs[lab].cascadeBuilt) built.push_back(lab);

        if (!built.empty()) {
            progress("grading...");
            std::vector<std::string> argv = gradeArguments(framework, options, studentDir, built);
            ProcessLimits limits = buildLimits(65536, FileAccess{}, {});   // stoa-grade confines its lab programs
            // Every case of every lab (and its cascade run) at its full limit, and then some.
            double perCase = options.timeoutSeconds > 0.0 ? options.timeoutSeconds : kUnrecordedTimeoutSeconds * 4.0;
            limits.timeoutSeconds = 60.0 + perCase * 4.0 * 64;
            ProcessOutcome grading = runProcess(argv, studentDir, limits);
            writeText(studentDir / "grade.log", grading.output);
            if (std::string note = strayNote("stoa-grade", grading); !note.empty()) grade.notes.push_back(note);
            if (!grading.exitedWith(0) || !std::filesystem::exists(studentDir / "results.json")) {
                grade.notes.push_back("stoa-grade " + grading.describe() + "; see grade.log: " +
                                      truncated(oneLine(grading.lastOutputLine()), kNoteLength));
                return finish("grader error");
            }
            addResults(studentDir / "results.json", grade);
        }
        if (!buildErrors.empty()) addBuildFailures(studentDir / "results.json", grade, buildErrors);
        return finish(buildErrors.empty() ? "graded" : built.empty() ? "build failed" : "partly built");
    } catch (const std::exception& error) {
        grade.notes.push_back(truncated(oneLine(error.what()), kNoteLength));
        return finish("grader error");
    }
}

namespace {

// The class report (ClassReport.hpp) beside the gradebook; a failure to write it
// is said and leaves the gradebook standing.
void writeClassPages(const ClassOptions& options, const Framework& framework, const std::vector<StudentGrade>& grades,
                     std::ostream& out, std::ostream& err) {
    auto start = std::chrono::steady_clock::now();
    try {
        writeClassReport(options.outDir, summarizeGrades(grades, framework, options.outDir));
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        out << "wrote " << (options.outDir / "class.html").string() << " and class.json ("
            << static_cast<int>(seconds * 1000.0 + 0.5) << " ms)" << std::endl;
    } catch (const std::exception& error) {
        err << "stoa-grade-class: no class report: " << error.what() << "\n";
    }
}

// --similarity: the staged copies of the submissions compared lab by lab.
// Returns 0 when the report was written, 1 when it could not be (SIM missing).
int compareStaged(const std::vector<StagedSubmission>& staged, const ClassOptions& options,
                  const Framework& framework, std::ostream& out, std::ostream& err) {
    std::map<std::string, std::filesystem::path> submissions;
    for (const StagedSubmission& submission : staged)
        if (!submission.labsDir.empty()) submissions[submission.submission.student] = submission.labsDir;
    out << "comparing " << submissions.size() << " submissions for similarity..." << std::endl;
    auto start = std::chrono::steady_clock::now();
    try {
        if (writeSimilarityReport(submissions, framework.sourceDir, framework.labs, options.outDir,
                                  SimilarityOptions{}, out, err) != 0)
            return 1;
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        out << "similarity took " << formatPoints(seconds) << " s" << std::endl;
        return 0;
    } catch (const std::exception& error) {
        err << "stoa-grade-class: no similarity report: " << error.what() << "\n";
        return 1;
    }
}

} // namespace

int runClassGrade(const ClassOptions& options, const Framework& framework, std::ostream& out, std::ostream& err) {
    auto start = std::chrono::steady_clock::now();
    std::vector<std::string> skipped;
    std::vector<Submission> submissions = findSubmissions(options.submissionsDir, skipped);
    for (const std::string& line : skipped) err << "note: skipping " << line << "\n";
    if (submissions.empty()) {
        err << "stoa-grade-class: no submissions in " << options.submissionsDir.string()
            << " (expected student folders, .zip or .tar.gz files)\n";
        return 1;
    }
    std::filesystem::create_directories(options.outDir);
    out << (options.similarityOnly ? "staging " : "grading ") << submissions.size() << " submissions (" << options.jobs << " at once), labs:";
    for (const std::string& lab : framework.labs) out << " " << lab;
    out << "\n" << (framework.gradeWritesHtml ? "" : "note: this stoa-grade has no --html; results.json only\n");

    std::mutex printing;
    std::size_t total = submissions.size();
    // Every submission is copied before any student's code is built or run.
    out << "staging " << total << " submissions into " << options.outDir.string() << "/STUDENT/submission"
        << std::endl;
    std::vector<StagedSubmission> staged(total);
    forEachInParallel(total, options.jobs, [&](std::size_t i) { staged[i] = stageForGrading(submissions[i], options); });
    if (std::string note = fileConfinementNote(); !note.empty()) err << "stoa-grade-class: " << note << "\n";
    if (options.similarityOnly) return compareStaged(staged, options, framework, out, err);

    std::size_t finished = 0;
    std::vector<StudentGrade> grades(total);
    forEachInParallel(total, options.jobs, [&](std::size_t i) {
        const Submission& submission = submissions[i];
        auto say = [&](const std::string& what) {
            std::lock_guard<std::mutex> lock(printing);
            out << "[" << (i + 1) << "/" << total << "] " << submission.student << ": " << what << std::endl;
        };
        grades[i] = gradeSubmission(staged[i], framework, options, say);
        std::lock_guard<std::mutex> lock(printing);
        ++finished;
        out << "[" << (i + 1) << "/" << total << "] " << submission.student << ": " << grades[i].status << " "
            << formatPoints(grades[i].points) << "/" << formatPoints(grades[i].maxPoints);
        for (const std::string& note : grades[i].notes) out << "\n      " << note;
        out << "  (" << finished << " of " << total << " done)" << std::endl;
    });

    // Every step killed what it left; this is the last look before the gradebook.
    if (std::size_t strays = killStrayProcesses())
        err << "stoa-grade-class: killed " << strays << " more processes the submissions had left running\n";
    // Grading only ever reads a submission: a change here means something got past the sandbox.
    for (std::size_t i = 0; i < total; ++i) {
        if (staged[i].inputs.empty()) continue;
        std::vector<std::string> changed = changedInputs(staged[i].inputs, recordInputs(submissions[i]));
        if (changed.empty()) continue;
        std::string list;
        for (const std::string& path : changed) list += (list.empty() ? "" : ", ") + path;
        grades[i].notes.push_back(truncated("the submission changed during grading (it was graded as it was "
                                            "before): " + list, kNoteLength));
        err << "stoa-grade-class: " << submissions[i].student << "'s submission changed during grading: " << list
            << "\n";
    }
    std::filesystem::path gradebook = options.outDir / "gradebook.csv";
    writeReportFile(gradebook, gradebookCsv(framework.labs, grades), "the gradebook");
    writeClassPages(options, framework, grades, out, err);
    if (options.similarity) compareStaged(staged, options, framework, out, err);   // the grades stand without it
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out << "wrote " << gradebook.string() << " (" << total << " students, " << static_cast<int>(seconds + 0.5)
        << " s); per student: " << (options.outDir / "STUDENT").string()
        << (framework.gradeWritesHtml ? "/{results.json,report.html,*.log}\n" : "/{results.json,*.log}\n");
    return 0;
}

} // namespace stoa::grader
