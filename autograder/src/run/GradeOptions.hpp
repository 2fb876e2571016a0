#pragma once
// What stoa-grade was asked to do: the options its command line (cli/CommandLine.hpp)
// fills in and the layers below read, and the error for a request that makes no sense.

#include "GradeResult.hpp"

#include <stoa/core/InputError.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stoa::grader {

/// Bad usage: stoa-grade prints it with the usage and exits with status 2.
class UsageError : public InputError {
public:
    explicit UsageError(const std::string& message) : InputError("", 0, message) {}
};

enum class Mode { Grade, UpdateReferences, CheckMistakes, Determinism, HeatMapLegend, Help };

struct Options {
    Mode mode = Mode::Grade;
    std::vector<std::string> labs;            // as given: "01_transforms" or "01"; empty = every built lab
    std::vector<std::string> cases;           // empty = every case of the selected labs
    std::filesystem::path binDir;             // empty = the folder stoa-grade runs from
    std::string backend;                      // "osmesa", "egl", or empty for the lab program's default
    std::filesystem::path jsonFile;           // Gradescope results.json; empty = none
    std::filesystem::path htmlFile;           // the self-contained HTML report; empty = none
    std::filesystem::path junitFile;          // JUnit XML; empty = none
    double timeoutSeconds = 0.0;              // per case, wall clock; 0: from the render times (RenderTimes.hpp)
    int jobs = 1;                             // cases rendered at once
    std::filesystem::path workDir;            // empty = a fresh folder under the system's temp dir
    std::filesystem::path shaderCache;        // --shader-cache: Mesa's cache for the lab programs; empty = the user's
    std::vector<std::filesystem::path> privateDirs;   // --private: kept from the lab programs (a class's submissions, grades)
    std::optional<GradeStatus> expect;        // Passed or NotAttempted: exit 1 unless every case has it
    bool everyCase = false;                   // --every-case: --check-mistakes (--check-hints) grades every
                                              // case of a mistake's lab, not only those its fails: line names
    std::filesystem::path outOfGalleryDir;    // --check-hints DIR: mistakes outside the gallery
                                              // (DIR/<lab>/mistakes/*.mistake), mode CheckMistakes
    std::filesystem::path heatMapLegend;      // --write-heatmap-legend FILE: mode HeatMapLegend
};

} // namespace stoa::grader
