#include "LabCommandLine.hpp"

#include "ProgramName.hpp"

#include <stoa/core/InputError.hpp>

#include <sstream>

namespace stoa::detail {

void printUsage(const LabBuildInfo& info, std::FILE* to) {
    std::fprintf(to,
                 "usage: %s [--case NAME] [--view live|yours|reference|difference] [--screenshot FILE]\n"
                 "       %s --render NAME --output FILE.png [--backend osmesa|egl]\n"
                 "       %s --check NAME|all [--backend osmesa|egl]\n"
                 "       %s --list | --list-checks | --info | --help\n"
                 "Any of them takes --cases FILE.ini: the cases from that manifest instead of the lab's\n"
                 "cases.ini (the grader's hidden cases).\n\n"
                 "Without --render or --check the lab opens a window; see docs/labs/%s.md.\n"
                 "Exit status: 0 done, 1 error, 2 bad command line, 3 not attempted (a stub is in place),\n"
                 "4 a property check does not hold.\n",
                 programName(info).c_str(), programName(info).c_str(), programName(info).c_str(),
                 programName(info).c_str(), info.name);
}

Options parseOptions(int argc, char** argv) {
    Options options;
    auto value = [&](int& i) -> std::string {
        if (i + 1 >= argc) throw InputError("", 0, std::string(argv[i]) + " needs a value");
        return argv[++i];
    };
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--list") options.list = true;
        else if (arg == "--list-checks") options.listChecks = true;
        else if (arg == "--check") options.check = value(i);
        else if (arg == "--info") options.info = true;
        else if (arg == "--help" || arg == "-h") options.help = true;
        else if (arg == "--render") options.renderCase = value(i);
        else if (arg == "--output") options.output = value(i);
        else if (arg == "--backend") options.backend = parseHeadlessBackend(value(i));
        else if (arg == "--case") options.windowCase = value(i);
        else if (arg == "--screenshot") options.screenshot = value(i);
        else if (arg == "--view") {
            const std::string name = value(i);
            const char* const views[] = {"live", "yours", "reference", "difference"};
            options.view = -1;
            for (int v = 0; v < 4; ++v)
                if (name == views[v]) options.view = v;
            if (options.view < 0)
                throw InputError("", 0, "--view takes live, yours, reference or difference, not '" + name + "'");
        }
        else if (arg == "--cases") options.casesFile = value(i);
        else
            throw InputError("", 0, "unknown argument '" + arg +
                                        "' (valid: --case, --view, --screenshot, --render, --output, --backend, --check, "
                                        "--cases, --list, --list-checks, --info, --help)");
    }
    if (!options.renderCase.empty() && options.output.empty())
        throw InputError("", 0, "--render needs --output FILE.png");
    if (!options.check.empty() && (!options.renderCase.empty() || !options.output.empty()))
        throw InputError("", 0, "--check runs property checks; it takes no --render or --output");
    if (!options.check.empty() && (!options.windowCase.empty() || !options.screenshot.empty() || options.view))
        throw InputError("", 0, "--case, --view and --screenshot are for the window; --check runs headless");
    if (options.renderCase.empty() && !options.output.empty())
        throw InputError("", 0, "--output goes with --render");
    if (options.renderCase.empty() && options.check.empty() && options.backend)
        throw InputError("", 0, "--backend goes with --render or --check");
    if (!options.renderCase.empty() && (!options.windowCase.empty() || !options.screenshot.empty() || options.view))
        throw InputError("", 0, "--case, --view and --screenshot are for the window; --render renders headless");
    return options;
}

std::vector<std::filesystem::path> splitSearchPath(const char* joined) {
    std::vector<std::filesystem::path> folders;
    std::stringstream stream(joined);
    std::string folder;
    while (std::getline(stream, folder, '|'))
        if (!folder.empty()) folders.emplace_back(folder);
    return folders;
}

const CaseSpec& findCase(const LabManifest& manifest, const std::string& name) {
    if (const CaseSpec* spec = manifest.find(name)) return *spec;
    throw InputError(manifest.file, 0, "no case '" + name + "' (cases: " + manifest.caseNames() + ")");
}

} // namespace stoa::detail
