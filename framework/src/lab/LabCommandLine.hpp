#pragma once
// runLab()'s command line (LabApp.hpp lists it): what it asks for, and the
// usage text. Private to framework/src/lab/.

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabBuildInfo.hpp>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stoa::detail {

struct Options {
    bool list = false;
    bool listChecks = false;
    std::string check;           // --check NAME or all: run property checks headless
    bool info = false;
    bool help = false;
    std::string renderCase;      // headless
    std::string output;
    std::optional<HeadlessBackend> backend;
    std::string windowCase;      // window
    std::string screenshot;
    int view = 0;                // --view: 0 live, 1 yours, 2 reference, 3 difference (the 'g' key's views)
    std::string casesFile;       // --cases: read the cases from this manifest instead of the lab's
};

void printUsage(const LabBuildInfo& info, std::FILE* to);
/// Throws InputError naming the argument that is wrong.
Options parseOptions(int argc, char** argv);
/// LabBuildInfo::shaderPath's folders ('|' between them).
std::vector<std::filesystem::path> splitSearchPath(const char* joined);
/// The case called `name`; InputError listing the cases when there is none.
const CaseSpec& findCase(const LabManifest& manifest, const std::string& name);

} // namespace stoa::detail
