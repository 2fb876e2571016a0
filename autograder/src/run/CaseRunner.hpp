#pragma once
// Renders one graded case with its lab program in a child process and grades
// the image against the reference.
//
//   <program> --render CASE --output <workDir>/rendered.png [--backend osmesa|egl] [--cases FILE]
//     exit 0: the image is written;  exit 3: not attempted (a stub threw);
//     exit 2: bad usage;  anything else: an error.

#include "ChildProcess.hpp"
#include "GradeResult.hpp"
#include "ReferenceGuard.hpp"
#include "RenderTimes.hpp"

#include <stoa/image/Image.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <filesystem>
#include <string>

namespace stoa::grader {

struct CaseJob {
    std::string lab;                      // "01_transforms"
    std::filesystem::path program;        // the lab program to run
    CaseSpec spec;                        // size, points, visibility, compare options
    std::filesystem::path reference;      // may not exist: the result is then "no reference"
    std::filesystem::path workDir;        // emptied and recreated; the program runs and writes there
    std::filesystem::path casesFile;      // passed as --cases when not empty: the manifest the case was planned
                                          // from (cases.ini or hidden_cases.ini), so the program reads the case
                                          // the grader planned, not one of its own
    bool cascade = false;                 // `program` is the lab's cascade program (Cascade.hpp)
    std::vector<std::string> environment; // more NAME=VALUE for this job's program (--determinism's variants)
    CaseTimeouts timeouts;                // from the solution's render time (RenderTimes.hpp)
};

struct RunSettings {
    ProcessLimits limits = defaultLimits(60.0);
    std::string backend;                  // passed as --backend when not empty
    bool caseTimeouts = false;            // gradeCases() applies each job's `timeouts` instead of limits' timeout
    /// What every lab program may read (labProgramBaseAccess(), LabSandbox.hpp);
    /// each job adds its build, its case folder and its track's files. Unconfined
    /// by default.
    FileAccess files;
    std::filesystem::path sourceDir;      // the Stoa tree whose solutions/ a job may be granted
    std::filesystem::path shaderCache;    // Mesa's shader cache for the lab programs; empty: Mesa's own choice
};

struct RenderOutcome {
    bool rendered = false;                // an image of the case's size was written and read back
    GradeStatus status = GradeStatus::Error;   // NotAttempted or Error when not rendered; for a
                                               // property check (no picture) Passed or Failed
    std::string reason;                   // why not rendered, in one line
    Image image;
    std::filesystem::path imagePath;      // <workDir>/rendered.png
    ProcessOutcome process;
};

/// Runs the program for one case, confined to the files labProgramAccess() gives
/// it (LabSandbox.hpp), with TMPDIR its case folder. Never throws: every failure
/// is an outcome.
RenderOutcome renderCase(const CaseJob& job, const RunSettings& settings);

/// The result of `job` before it is graded: its names, points and reference, no status yet.
GradeResult ungradedResult(const CaseJob& job);

/// renderCase(), then the comparison with the reference; for a failed case the
/// heat map is written to <workDir>/heatmap.png. Never throws. With a `guard`, the
/// reference comes from the guard's copy, and a case after which a guarded file
/// changed fails as "tried to modify the reference images" (the files are restored).
GradeResult gradeCase(const CaseJob& job, const RunSettings& settings, ReferenceGuard* guard = nullptr);

/// The reason for exit status 3: "not implemented: Camera::viewMatrix()" from the
/// program's last line "stoa: not implemented: Camera::viewMatrix()".
std::string notAttemptedReason(const ProcessOutcome& process);

} // namespace stoa::grader
