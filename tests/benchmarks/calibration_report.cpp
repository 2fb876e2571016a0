// calibration_report SOURCE_DIR BUILD_DIR: the margins of the image comparison.
// Reads the pictures the e2e tests leave in BUILD_DIR/e2e/**/LAB/CASE/rendered.png
// (run `ctest -R e2e` first), compares each with its reference
// (autograder/references/LAB/CASE.png or solutions/LAB/references/CASE.png) and
// prints, per group of runs, the largest max error, bad fraction and FLIP mean
// (FLIP always computed here, also where the grader's fast path skips it):
//   must pass   solutions-*, caps-* (other instruction sets), equivalents/*
//   must fail   mistakes/*, only the cases the mistake's `fails:` line names,
//               where the smallest values matter.
// Renders nothing. docs/instructor-guide.md, "Calibration and margins", has the table.

#include <stoa/core/InputError.hpp>
#include <stoa/image/Flip.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {

struct Extremes {
    int count = 0;
    double maxError[2] = {1e9, -1};     // smallest, largest
    double badFraction[2] = {1e9, -1};
    double flipMean[2] = {1e9, -1};
    std::string worst;                  // the run with the largest FLIP mean (must pass) or smallest (must fail)

    void add(double error, double bad, double flip, const std::string& where, bool mustFail) {
        ++count;
        const auto update = [](double (&range)[2], double value) {
            range[0] = std::min(range[0], value);
            range[1] = std::max(range[1], value);
        };
        if (mustFail ? flip < flipMean[0] : flip > flipMean[1]) worst = where;
        update(maxError, error);
        update(badFraction, bad);
        update(flipMean, flip);
    }
};

// The cases a mistake must fail: its `fails:` line.
std::set<std::string> mustFailCases(const fs::path& source, const std::string& lab, const std::string& mistake) {
    std::ifstream in(source / "solutions" / lab / "mistakes" / (mistake + ".mistake"));
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("fails:", 0) == 0) {
            std::istringstream words(line.substr(6));
            std::set<std::string> cases;
            for (std::string word; words >> word;) cases.insert(word);
            return cases;
        }
    return {};
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: calibration_report SOURCE_DIR BUILD_DIR\n");
        return 2;
    }
    const fs::path source = argv[1], e2e = fs::path(argv[2]) / "e2e";
    if (!fs::is_directory(e2e)) {
        std::fprintf(stderr, "calibration_report: %s does not exist; run ctest -R e2e first\n", e2e.c_str());
        return 2;
    }
    std::map<std::string, Extremes> groups;
    for (const auto& entry : fs::recursive_directory_iterator(e2e)) {
        if (entry.path().filename() != "rendered.png") continue;
        const fs::path caseDir = entry.path().parent_path();
        const std::string caseName = caseDir.filename().string(), lab = caseDir.parent_path().filename().string();
        const std::string run = fs::relative(caseDir.parent_path().parent_path(), e2e).string();
        std::string group;
        bool mustFail = false;
        if (run.rfind("mistakes/", 0) == 0) {
            const std::string id = fs::path(run).filename().string();  // LAB.MISTAKE
            const std::string mistake = id.substr(id.find('.') + 1);
            if (!mustFailCases(source, lab, mistake).count(caseName)) continue;
            group = "mistakes (must-fail cases)";
            mustFail = true;
        } else if (run.rfind("solutions-", 0) == 0) {
            group = "solutions, both backends";
        } else if (run.rfind("caps-", 0) == 0) {
            group = "solutions, " + run.substr(5);
        } else if (run.rfind("equivalents/", 0) == 0) {
            group = "equivalents";
        } else {
            continue;  // stubs, reports, ...: not calibration
        }
        fs::path reference = source / "autograder" / "references" / lab / (caseName + ".png");
        if (!fs::exists(reference)) reference = source / "solutions" / lab / "references" / (caseName + ".png");
        if (!fs::exists(reference)) continue;
        try {
            const stoa::Image actual = stoa::Image::load(entry.path()), expected = stoa::Image::load(reference);
            const stoa::CompareResult result = stoa::compareImages(actual, expected);
            if (!result.sameSize) continue;
            const double flip = result.flipErrorMap.empty() ? stoa::computeFlip(actual, expected).mean : result.flipMean;
            groups[group].add(result.maxError, result.badFraction, flip, run + " " + lab + "/" + caseName, mustFail);
        } catch (const stoa::InputError& error) {
            std::fprintf(stderr, "calibration_report: %s\n", error.what());
        }
    }
    // What the shift-tolerant gate lets through by design: every reference moved by one pixel.
    for (const fs::path& labs : {source / "autograder" / "references", source / "solutions"}) {
        if (!fs::is_directory(labs)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(labs)) {
            // autograder/references/LAB/CASE.png and solutions/LAB/references/CASE.png only (not the mistake gallery).
            const fs::path folder = entry.path().parent_path();
            const bool isReference = labs.filename() == "solutions" ? folder.filename() == "references"
                                                                    : folder.parent_path() == labs;
            if (entry.path().extension() != ".png" || !isReference) continue;
            const stoa::Image expected = stoa::Image::load(entry.path());
            stoa::Image shifted = expected;
            for (int y = 0; y < expected.height(); ++y)
                for (int x = 1; x < expected.width(); ++x) shifted.setPixel(x, y, expected.pixel(x - 1, y));
            const stoa::CompareResult result = stoa::compareImages(shifted, expected);
            const double flip = result.flipErrorMap.empty() ? stoa::computeFlip(shifted, expected).mean : result.flipMean;
            groups["references shifted 1 px"].add(result.maxError, result.badFraction, flip, entry.path().string(),
                                                  false);
        }
    }
    std::printf("%-34s %5s %13s %17s %17s  %s\n", "group", "runs", "max error", "bad fraction", "FLIP mean",
                "extreme FLIP mean at");
    for (const auto& [name, e] : groups)
        std::printf("%-34s %5d %5.0f..%-6.0f %7.4f..%-8.4f %.1e..%-8.1e  %s\n", name.c_str(), e.count, e.maxError[0],
                    e.maxError[1], e.badFraction[0], e.badFraction[1], e.flipMean[0], e.flipMean[1], e.worst.c_str());
    return 0;
}
