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
//   --list                     print the names of the cases that render a picture
//   --list-checks              print the names of the property checks (PropertyCheck.hpp)
//   --check NAME|all [--backend osmesa|egl]
//                              run a property check (or all), headless, and print the verdicts
//   --info                     print the lab and the track it was built from
//   --render NAME --output FILE [--backend osmesa|egl]
//                              render a case headless into a PNG
//   --cases FILE.ini           with any of the above: the cases come from FILE.ini
//                              instead of the lab's cases.ini (the grader passes the
//                              manifest it planned each case from this way)
// Exit status: 0 done; 1 error; 2 bad command line; 3 not attempted (a stub is still in place);
// 4 a property check does not hold.

#include <stoa/lab/Lab.hpp>
#include <stoa/lab/LabBuildInfo.hpp>
#include <stoa/lab/LabProtocol.hpp>   // the exit codes

#include <string>
#include <vector>

namespace stoa {

int runLab(Lab& lab, const LabBuildInfo& info, int argc, char** argv);

/// For a tool built on a lab's app (stoa-crowds, stoa-editor): runs `lab` on
/// the case `caseName` of the manifest text `cases`, parsed in memory (no file
/// is written). `options` are the tool's own flags for it: `--render FILE` (the
/// case's picture, headless), `--screenshot FILE`, `--backend NAME`; without
/// --render the case opens in a window. `program` is argv[0]: its file name
/// names the tool in messages; `title` is the window's ("Stoa editor -- FILE").
int runLabOnCase(Lab& lab, const LabBuildInfo& info, const std::string& program, const std::string& title,
                 const std::string& cases, const std::string& caseName, const std::vector<std::string>& options);

} // namespace stoa

#define STOA_LAB_BUILD_INFO ::stoa::labBuildInfo()
