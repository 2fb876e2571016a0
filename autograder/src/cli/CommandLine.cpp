#include "CommandLine.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace stoa::grader {

namespace {

const char* const kOptionList =
    "--lab, --case, --bin-dir, --backend, --json, --html, --junit, --timeout, --jobs, --work-dir, --shader-cache, --private, --expect, "
    "--update-references, --check-mistakes, --check-hints, --determinism, --write-heatmap-legend, --help";

double parsePositiveNumber(const std::string& option, const std::string& text) {
    errno = 0;
    char* end = nullptr;
    double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value) || value <= 0)
        throw UsageError(option + " expects a positive number of seconds, got '" + text + "'");
    return value;
}

int parseJobCount(const std::string& text) {
    errno = 0;
    char* end = nullptr;
    long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno != 0 || value < 1 || value > 256)
        throw UsageError("--jobs expects a whole number from 1 to 256, got '" + text + "'");
    return static_cast<int>(value);
}

} // namespace

Options parseCommandLine(const std::vector<std::string>& arguments) {
    Options options;
    bool updateReferences = false;
    bool checkMistakes = false;
    bool determinism = false;
    bool help = false;

    for (std::size_t i = 0; i < arguments.size(); ++i) {
        std::string option = arguments[i];
        std::optional<std::string> inlineValue;
        if (option.rfind("--", 0) == 0) {
            std::size_t equals = option.find('=');
            if (equals != std::string::npos) {
                inlineValue = option.substr(equals + 1);
                option = option.substr(0, equals);
            }
        }
        auto takeValue = [&](const char* what) -> std::string {
            if (inlineValue) {
                if (inlineValue->empty()) throw UsageError(option + " needs " + what + " after '='");
                return *inlineValue;
            }
            if (i + 1 >= arguments.size() || arguments[i + 1].rfind("--", 0) == 0)
                throw UsageError(option + " needs " + what);
            return arguments[++i];
        };
        auto noValue = [&]() {
            if (inlineValue) throw UsageError(option + " takes no value");
        };

        if (option == "--lab") {
            options.labs.push_back(takeValue("a lab, such as 01_transforms or 01"));
        } else if (option == "--case") {
            options.cases.push_back(takeValue("a case name, such as orbit_front"));
        } else if (option == "--bin-dir") {
            options.binDir = takeValue("a folder with the lab programs, such as build/bin");
        } else if (option == "--backend") {
            options.backend = takeValue("osmesa or egl");
            if (options.backend != "osmesa" && options.backend != "egl")
                throw UsageError("--backend must be osmesa or egl, got '" + options.backend + "'");
        } else if (option == "--json") {
            options.jsonFile = takeValue("a file to write, such as results.json");
        } else if (option == "--html") {
            options.htmlFile = takeValue("a file to write, such as report.html");
        } else if (option == "--junit") {
            options.junitFile = takeValue("a file to write, such as junit.xml");
        } else if (option == "--timeout") {
            options.timeoutSeconds = parsePositiveNumber(option, takeValue("a number of seconds"));
        } else if (option == "--jobs") {
            options.jobs = parseJobCount(takeValue("a number of cases to render at once"));
        } else if (option == "--work-dir") {
            options.workDir = takeValue("a folder for the rendered images");
        } else if (option == "--shader-cache") {
            options.shaderCache = takeValue("a folder for Mesa's shader cache");
        } else if (option == "--private") {
            options.privateDirs.push_back(takeValue("a folder the lab programs may not see"));
        } else if (option == "--expect") {
            std::string status = takeValue("pass or not-attempted");
            if (status == "pass")
                options.expect = GradeStatus::Passed;
            else if (status == "not-attempted")
                options.expect = GradeStatus::NotAttempted;
            else
                throw UsageError("--expect must be pass or not-attempted, got '" + status + "'");
        } else if (option == "--update-references") {
            noValue();
            updateReferences = true;
        } else if (option == "--determinism") {
            noValue();
            determinism = true;
        } else if (option == "--check-mistakes") {
            noValue();
            checkMistakes = true;
        } else if (option == "--check-hints") {
            options.outOfGalleryDir = takeValue("a folder of mistakes outside the gallery (<lab>/mistakes/*.mistake)");
            checkMistakes = true;
        } else if (option == "--write-heatmap-legend") {
            options.heatMapLegend = takeValue("a PNG file to write");
        } else if (option == "--help" || option == "-h") {
            noValue();
            help = true;
        } else if (option.rfind("-", 0) == 0) {
            throw UsageError("unknown option '" + option + "'; the options are " + kOptionList);
        } else {
            throw UsageError("unexpected argument '" + option + "' (did you mean --lab " + option +
                             " or --case " + option + "?)");
        }
    }

    if (help) {
        options.mode = Mode::Help;
        return options;
    }
    if (updateReferences && checkMistakes)
        throw UsageError("--update-references and --check-mistakes cannot be combined; run them one after the other");
    if (updateReferences) options.mode = Mode::UpdateReferences;
    if (checkMistakes) options.mode = Mode::CheckMistakes;
    if (determinism && (updateReferences || checkMistakes))
        throw UsageError("--determinism cannot be combined with --update-references or --check-mistakes");
    if (determinism) options.mode = Mode::Determinism;
    if (!options.heatMapLegend.empty()) {
        if (updateReferences || checkMistakes || determinism)
            throw UsageError("--write-heatmap-legend cannot be combined with another mode");
        options.mode = Mode::HeatMapLegend;
    }
    if (options.mode != Mode::Grade) {
        const char* modeName = updateReferences                   ? "--update-references"
                               : !options.outOfGalleryDir.empty() ? "--check-hints"
                               : checkMistakes                    ? "--check-mistakes"
                               : determinism                      ? "--determinism"
                                                                  : "--write-heatmap-legend";
        if (options.expect) throw UsageError(std::string("--expect only applies to grading, not to ") + modeName);
        if (!options.jsonFile.empty())
            throw UsageError(std::string("--json only applies to grading, not to ") + modeName);
        if (!options.htmlFile.empty())
            throw UsageError(std::string("--html only applies to grading, not to ") + modeName);
        if (!options.junitFile.empty())
            throw UsageError(std::string("--junit only applies to grading, not to ") + modeName);
    }
    if (checkMistakes && !options.cases.empty())
        throw UsageError("--check-mistakes checks the cases each mistake names in 'fails:'; drop --case");
    return options;
}

std::string usageText() {
    return R"(stoa-grade: renders the labs' graded cases and compares them with the reference images.

usage:
  stoa-grade [--lab NN_name|NN]... [--case NAME]... [options]   grade (every built lab by default)
  stoa-grade --update-references [--lab ...] [--case ...]       write reference images (solutions build)
  stoa-grade --check-mistakes [--lab ...]                       check that each planted mistake is caught
  stoa-grade --check-hints DIR [--lab ...]                      check that mistakes outside the gallery (DIR/<lab>/mistakes/)
                                                                get no hint naming another cause
  stoa-grade --write-heatmap-legend FILE                        write the heat map's colour legend as a PNG
  stoa-grade --determinism [--lab ...] [--case ...]             render each case twice and with LP_NUM_THREADS=1
                                                                and 2; exit 1 on any difference
  stoa-grade --help

options:
  --lab NN_name|NN         grade this lab (repeatable), e.g. --lab 01_transforms or --lab 01
  --case NAME              grade only this case (repeatable)
  --bin-dir DIR            where the lab programs are (default: the folder of stoa-grade)
  --backend osmesa|egl     the headless context the lab programs use (default: theirs)
  --json FILE              also write Gradescope's results.json to FILE
  --html FILE              also write a self-contained HTML report (images, metrics, hints) to FILE
  --junit FILE             also write JUnit XML (one testsuite per lab) to FILE
  --timeout SECONDS        wall-clock limit per case (default: 10 x the solution's recorded
                           render time, at least 15 s; 3 x, at least 2 s, for the remaining
                           cases of a program that has timed out once)
  --jobs N                 render N cases at once (default 1)
  --work-dir DIR           where rendered images and heat maps go (default: a new temp folder)
  --shader-cache DIR       Mesa's shader cache for the lab programs (default: this user's);
                           besides its case folder, the one folder a lab program may write
  --private DIR            a folder the lab programs may not read (repeatable; stoa-grade-class
                           names the submissions and the grades)
  --expect pass|not-attempted
                           exit 1 unless every graded case has that status

exit status: 0 when grading ran (whatever the score), 1 on failure (or an unmet
--expect, or an uncaught mistake), 2 on bad usage.
)";
}

} // namespace stoa::grader
