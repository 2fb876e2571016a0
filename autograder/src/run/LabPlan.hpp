#pragma once
// What one run of stoa-grade works on: the selected labs, read from their
// manifests, with the selected cases, and the jobs that render them.

#include "CaseRunner.hpp"
#include "GradeOptions.hpp"
#include "LabCatalog.hpp"

#include <stoa/lab/CaseManifest.hpp>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace stoa::grader {

/// The folders a run uses and where it prints.
struct Environment {
    std::filesystem::path sourceDir;   // the repository root (labs/, solutions/, autograder/references/)
    std::filesystem::path binDir;      // the lab programs
    std::ostream& out;                 // the report
    std::ostream& err;                 // notes and progress
    /// err is a terminal: progress is one line, rewritten in place and cleared
    /// when the cases are done (a log gets a line per case).
    bool progressInPlace = false;
};

struct PlannedLab {
    std::string lab;                   // "01_transforms"
    LabManifest manifest;
    std::vector<CaseSpec> cases;       // the manifest's cases that --case selects (all without --case)
    std::filesystem::path program;     // <bin>/labNN_name; may not exist when not required
    std::filesystem::path hiddenManifest;   // solutions/NN_name/hidden_cases.ini when it exists, else empty
    std::filesystem::path cascadeProgram;   // <bin>/cascade/labNN_name when it is built, else empty (Cascade.hpp)
};

/// Reads a lab's hidden cases (solutions/NN_name/hidden_cases.ini) into the end
/// of `lab.manifest`, each marked hidden. Throws InputError naming the file when
/// it is for another lab or repeats a public case's name.
void addHiddenCases(PlannedLab& lab, const std::filesystem::path& hiddenManifest);

/// The labs --lab selects (all labs without it), with their manifests (public and,
/// where solutions/ has them, hidden cases) and the cases --case selects. With
/// `requirePrograms`, a lab with neither its program nor a cascade program built
/// is left out with a note on `env.err`. Throws UsageError for an unknown
/// lab or case, InputError for a manifest that does not parse.
/// The labs to run. With `requirePrograms`, a lab without a program is
/// skipped with a note, and a program older than a student file it was built
/// from (staleSources()) stops the run: a std::runtime_error that names the
/// files and the command that rebuilds.
std::vector<PlannedLab> planLabs(const Options& options, const Environment& env, bool requirePrograms);

/// The compiled student files newer than `program`, from the list its build
/// wrote beside it (<program>.sources, framework/cmake/StoaLab.cmake); none
/// when there is no list. `buildDir` gets the build folder the list names.
std::vector<std::filesystem::path> staleSources(const std::filesystem::path& program, std::filesystem::path& buildDir);

/// One job per selected case of `lab`, run by `program`, each in its own folder
/// <workDir>/<lab>/<case>. Each job passes the program --cases <the manifest the
/// case was planned from> (labs/NN_name/cases.ini, or hidden_cases.ini), so the
/// grader and the program read one file; a hidden case compares with
/// solutions/NN_name/references/CASE.png. With `cascade`, the jobs
/// are marked as the lab's cascade run and work in <workDir>/cascade/<lab>/<case>.
std::vector<CaseJob> caseJobs(const PlannedLab& lab, const std::filesystem::path& program,
                              const std::filesystem::path& sourceDir, const std::filesystem::path& workDir,
                              bool cascade = false);

/// The limits and backend from the command line, and the files the lab programs
/// may touch (LabSandbox.hpp): `sourceDir`'s public folders to read, their case
/// folders under `workDir` and the shader cache (--shader-cache, else Mesa's
/// own for this user) to write.
RunSettings runSettings(const Options& options, const std::filesystem::path& sourceDir,
                        const std::filesystem::path& workDir);

} // namespace stoa::grader
