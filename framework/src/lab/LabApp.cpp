// runLab(): the command line decides between the headless render
// (HeadlessRender.cpp), the window (LabWindow.cpp, with the in-window
// comparison of CaseComparison.cpp) and the quick answers (--list, --info).

#include "HeadlessRender.hpp"
#include "LabCommandLine.hpp"
#include "LabWindow.hpp"
#include "ProgramName.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/lab/LabApp.hpp>

#include <cstdio>
#include <filesystem>
#include <vector>

namespace stoa {

using namespace detail;

CheckResult Lab::runCheck(const CaseSpec& spec) {
    spec.reject("check", "this lab has no property check '" + spec.check + "'");
}

LabResources::LabResources(std::vector<std::filesystem::path> shaderSearchPath)
    : m_searchPath(std::move(shaderSearchPath)) {}

LabResources::~LabResources() = default;

Program& LabResources::loadProgram(const std::string& vertexFile, const std::string& fragmentFile) {
    m_programs.push_back(std::make_unique<Program>(Program::fromFiles(vertexFile, fragmentFile, m_searchPath)));
    return *m_programs.back();
}

namespace {

// What a run does with its manifest: list, check, render headless or open the window.
int runOnManifest(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options, int argc,
                  char** argv) {
    if (!manifest.lab.empty() && manifest.lab != info.name)
        throw InputError(manifest.file, 0, "these are the cases of lab " + manifest.lab + ", not of lab " + info.name);
    if (options.list || options.listChecks) {
        for (const CaseSpec& spec : manifest.cases)
            if (spec.check.empty() == options.list) std::printf("%s\n", spec.name.c_str());
        return kExitOk;
    }
    if (!options.check.empty()) return runChecks(lab, info, manifest, options);
    if (!options.renderCase.empty() && !manifest.find(options.renderCase)) {
        std::fprintf(stderr, "%s: no case '%s' (cases: %s)\n", programName(info).c_str(), options.renderCase.c_str(),
                     manifest.caseNames().c_str());
        return kExitUsage;
    }
    if (!options.renderCase.empty()) return renderHeadless(lab, info, manifest, options);
    return runWindow(lab, info, manifest, options, argc, argv);
}

// Runs `body`, turning a stub, bad input or any other failure into its message
// and the exit status the grader reads (LabProtocol.hpp).
template <typename Body>
int reportingFailures(const LabBuildInfo& info, Body&& body) {
    try {
        return body();
    } catch (const NotImplemented& stub) {
        std::fprintf(stderr, "%s\n", notImplementedLine(stub.describe(info.name)).c_str());
        return kExitNotAttempted;
    } catch (const ShaderNotImplemented& stub) {
        std::fprintf(stderr, "%s\n", notImplementedLine(stub.what()).c_str());
        return kExitNotAttempted;
    } catch (const InputError& error) {
        std::fprintf(stderr, "%s: %s\n", programName(info).c_str(), error.what());
        return kExitError;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: %s\n", programName(info).c_str(), error.what());
        return kExitError;
    }
}

} // namespace

int runLab(Lab& lab, const LabBuildInfo& info, int argc, char** argv) {
    return reportingFailures(info, [&]() -> int {
        Options options;
        try {
            options = parseOptions(argc, argv);
        } catch (const InputError& error) {
            std::fprintf(stderr, "%s: %s\n", programName(info).c_str(), error.what());
            printUsage(info, stderr);
            return kExitUsage;
        }
        if (options.help) {
            printUsage(info, stdout);
            return kExitOk;
        }
        if (options.info) {
            std::printf("lab=%s\ntrack=%s\n", info.name, info.track);
            return kExitOk;
        }
        // --cases replaces the lab's manifest (it does not add to it): the grader
        // passes the manifest it planned each case from.
        const LabManifest manifest = loadManifest(options.casesFile.empty()
                                                      ? std::filesystem::path(info.labDirectory) / "cases.ini"
                                                      : std::filesystem::path(options.casesFile));
        return runOnManifest(lab, info, manifest, options, argc, argv);
    });
}

int runLabOnCase(Lab& lab, const LabBuildInfo& labInfo, const std::string& program, const std::string& title,
                 const std::string& cases, const std::string& caseName, const std::vector<std::string>& options) {
    const std::string name = std::filesystem::path(program).filename().string();
    LabBuildInfo info = labInfo;
    info.programName = name.c_str();
    info.windowTitle = title.c_str();
    // The tool's flags, as the lab's command line spells them (argv also goes
    // to the window toolkit).
    std::vector<std::string> args{program};
    bool render = false;
    for (std::size_t i = 0; i < options.size(); ++i) {
        if (options[i] == "--render" && i + 1 < options.size()) {
            args.insert(args.end(), {"--render", caseName, "--output", options[++i]});
            render = true;
        } else {
            args.push_back(options[i]);
        }
    }
    if (!render) args.insert(args.end(), {"--case", caseName});
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    const int argc = static_cast<int>(args.size());
    return reportingFailures(info, [&]() -> int {
        const Options parsed = parseOptions(argc, argv.data());
        const LabManifest manifest = parseManifest(cases, name + "'s case");
        return runOnManifest(lab, info, manifest, parsed, argc, argv.data());
    });
}

} // namespace stoa
