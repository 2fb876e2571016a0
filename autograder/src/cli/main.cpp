// stoa-grade: renders the labs' graded cases in child processes, compares them
// with the reference images, and reports (see CommandLine.hpp for the usage).

#include "ChildProcess.hpp"
#include "CommandLine.hpp"
#include "DeterminismCheck.hpp"
#include "GradeCommand.hpp"
#include "HeatMapLegend.hpp"
#include "LabCatalog.hpp"
#include "LabPlan.hpp"
#include "MistakeCheck.hpp"
#include "ReferenceUpdate.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>

#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>

#include <unistd.h>

namespace {

// Progress as one line rewritten in place: on a terminal that understands it.
bool progressOnTerminal() {
    const char* term = std::getenv("TERM");
    return isatty(STDERR_FILENO) && term != nullptr && std::strcmp(term, "dumb") != 0;
}

} // namespace

int main(int argc, char** argv) {
    using namespace stoa::grader;
    try {
        Options options = parseCommandLine(std::vector<std::string>(argv + 1, argv + argc));
        if (options.mode == Mode::Help) {
            std::cout << usageText();
            return 0;
        }
        if (options.mode == Mode::HeatMapLegend) {
            writeHeatMapLegend(options.heatMapLegend);
            std::cout << "wrote " << options.heatMapLegend.string() << "\n";
            return 0;
        }
        killChildrenOnInterrupt();
        std::filesystem::path binDir = options.binDir.empty() ? executableDir() : options.binDir;
        if (binDir.empty()) {
            std::cerr << "stoa-grade: cannot tell which folder it runs from; pass --bin-dir\n";
            return 1;
        }
        if (!std::filesystem::is_directory(binDir)) {
            std::cerr << "stoa-grade: --bin-dir " << binDir.string() << " is not a folder\n";
            return 1;
        }
        Environment env{stoa::paths::sourceDir(), std::filesystem::absolute(binDir), std::cout, std::cerr,
                        progressOnTerminal()};
        switch (options.mode) {
        case Mode::Grade: return runGrade(options, env);
        case Mode::UpdateReferences: return runUpdateReferences(options, env);
        case Mode::CheckMistakes: return runCheckMistakes(options, env);
        case Mode::Determinism: return runDeterminismCheck(options, env);
        case Mode::HeatMapLegend:
        case Mode::Help: break;
        }
        return 0;
    } catch (const UsageError& error) {
        std::cerr << "stoa-grade: " << error.what() << "\n(run stoa-grade --help for the usage)\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "stoa-grade: " << error.what() << "\n";
        return 1;
    }
}
