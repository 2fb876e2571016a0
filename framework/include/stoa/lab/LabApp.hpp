#pragma once
// The main() of every lab app:
//
//   int main(int argc, char** argv) {
//       ShadingLab lab;
//       return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
//   }
//
// Command line (labNN_name --help prints it):
//   (no arguments)             open the window at the first case's view
//   --case NAME                open the window at that case
//   --screenshot FILE          with the window: draw the case, save the frame as PNG, quit
//   --list                     print the case names
//   --info                     print the lab and the track it was built from
//   --render NAME --output FILE [--backend osmesa|egl]
//                              render a case headless into a PNG
//   --cases FILE.ini           with any of the above: the cases come from FILE.ini
//                              instead of the lab's cases.ini (the grader passes a
//                              lab's hidden_cases.ini this way)
// Exit status: 0 done; 1 error; 2 bad command line; 3 not attempted (a stub is still in place).

#include <stoa/lab/Lab.hpp>

#include <string>

namespace stoa {

/// Where a lab program's files are, baked in by stoa_add_lab() (framework/cmake/StoaLab.cmake).
struct LabBuildInfo {
    const char* name;          // "01_transforms"
    const char* track;         // "labs", "solutions" or "mistake:NAME"
    const char* labDirectory;  // labs/01_transforms (its cases.ini)
    const char* shaderPath;    // folders separated by '|'
};

int runLab(Lab& lab, const LabBuildInfo& info, int argc, char** argv);

/// This program's build info. Not written by hand: the build generates one
/// definition per lab program (framework/cmake/StoaLab.cmake), so that a lab's
/// app sources compile once for all its programs (solution, stubs, mistakes, ...).
LabBuildInfo labBuildInfo();

enum ExitCode { kExitOk = 0, kExitError = 1, kExitUsage = 2, kExitNotAttempted = 3 };

} // namespace stoa

#define STOA_LAB_BUILD_INFO ::stoa::labBuildInfo()
