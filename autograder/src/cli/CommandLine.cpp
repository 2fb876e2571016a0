#include "CommandLine.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace stoa::grader {

namespace {

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

// The modes asked for; which one runs is decided once every option is read.
struct ModeFlags {
    bool updateReferences = false;
    bool checkMistakes = false;
    bool determinism = false;
    bool help = false;
};

// One option: its name, what its value is (nullptr: it takes none), and what it sets.
struct OptionSpec {
    const char* name;
    const char* value;
    void (*apply)(Options& options, ModeFlags& modes, const std::string& value);
};

const std::vector<OptionSpec>& optionTable() {
    static const std::vector<OptionSpec> table = {
        {"--lab", "a lab, such as 01_transforms or 01",
         [](Options& o, ModeFlags&, const std::string& v) { o.labs.push_back(v); }},
        {"--case", "a case name, such as orbit_front",
         [](Options& o, ModeFlags&, const std::string& v) { o.cases.push_back(v); }},
        {"--bin-dir", "a folder with the lab programs, such as build/bin",
         [](Options& o, ModeFlags&, const std::string& v) { o.binDir = v; }},
        {"--backend", "osmesa or egl",
         [](Options& o, ModeFlags&, const std::string& v) {
             if (v != "osmesa" && v != "egl") throw UsageError("--backend must be osmesa or egl, got '" + v + "'");
             o.backend = v;
         }},
        {"--json", "a file to write, such as results.json",
         [](Options& o, ModeFlags&, const std::string& v) { o.jsonFile = v; }},
        {"--html", "a file to write, such as report.html",
         [](Options& o, ModeFlags&, const std::string& v) { o.htmlFile = v; }},
        {"--junit", "a file to write, such as junit.xml",
         [](Options& o, ModeFlags&, const std::string& v) { o.junitFile = v; }},
        {"--timeout", "a number of seconds",
         [](Options& o, ModeFlags&, const std::string& v) { o.timeoutSeconds = parsePositiveNumber("--timeout", v); }},
        {"--jobs", "a number of cases to render at once",
         [](Options& o, ModeFlags&, const std::string& v) { o.jobs = parseJobCount(v); }},
        {"--work-dir", "a folder for the rendered images",
         [](Options& o, ModeFlags&, const std::string& v) { o.workDir = v; }},
        {"--shader-cache", "a folder for Mesa's shader cache",
         [](Options& o, ModeFlags&, const std::string& v) { o.shaderCache = v; }},
        {"--private", "a folder the lab programs may not see",
         [](Options& o, ModeFlags&, const std::string& v) { o.privateDirs.push_back(v); }},
        {"--expect", "pass or not-attempted",
         [](Options& o, ModeFlags&, const std::string& v) {
             if (v == "pass") o.expect = GradeStatus::Passed;
             else if (v == "not-attempted") o.expect = GradeStatus::NotAttempted;
             else throw UsageError("--expect must be pass or not-attempted, got '" + v + "'");
         }},
        {"--update-references", nullptr, [](Options&, ModeFlags& m, const std::string&) { m.updateReferences = true; }},
        {"--check-mistakes", nullptr, [](Options&, ModeFlags& m, const std::string&) { m.checkMistakes = true; }},
        {"--every-case", nullptr, [](Options& o, ModeFlags&, const std::string&) { o.everyCase = true; }},
        {"--check-hints", "a folder of mistakes outside the gallery (<lab>/mistakes/*.mistake)",
         [](Options& o, ModeFlags& m, const std::string& v) {
             o.outOfGalleryDir = v;
             m.checkMistakes = true;
         }},
        {"--determinism", nullptr, [](Options&, ModeFlags& m, const std::string&) { m.determinism = true; }},
        {"--write-heatmap-legend", "a PNG file to write",
         [](Options& o, ModeFlags&, const std::string& v) { o.heatMapLegend = v; }},
        {"--help", nullptr, [](Options&, ModeFlags& m, const std::string&) { m.help = true; }},
    };
    return table;
}

// "--lab, --case, ..., --help": every option, for the message about an unknown one.
std::string optionList() {
    std::string list;
    for (const OptionSpec& spec : optionTable()) list += (list.empty() ? "" : ", ") + std::string(spec.name);
    return list;
}

const OptionSpec& findOption(const std::string& option) {
    const std::string name = option == "-h" ? "--help" : option;
    for (const OptionSpec& spec : optionTable())
        if (name == spec.name) return spec;
    if (option.rfind("-", 0) == 0)
        throw UsageError("unknown option '" + option + "'; the options are " + optionList());
    throw UsageError("unexpected argument '" + option + "' (did you mean --lab " + option + " or --case " + option + "?)");
}

// The mode the flags ask for, and the options that do not go with it.
void chooseMode(Options& options, const ModeFlags& modes) {
    if (modes.help) {
        options.mode = Mode::Help;
        return;
    }
    if (modes.updateReferences && modes.checkMistakes)
        throw UsageError("--update-references and --check-mistakes cannot be combined; run them one after the other");
    if (modes.updateReferences) options.mode = Mode::UpdateReferences;
    if (modes.checkMistakes) options.mode = Mode::CheckMistakes;
    if (modes.determinism && (modes.updateReferences || modes.checkMistakes))
        throw UsageError("--determinism cannot be combined with --update-references or --check-mistakes");
    if (modes.determinism) options.mode = Mode::Determinism;
    if (!options.heatMapLegend.empty()) {
        if (modes.updateReferences || modes.checkMistakes || modes.determinism)
            throw UsageError("--write-heatmap-legend cannot be combined with another mode");
        options.mode = Mode::HeatMapLegend;
    }
    if (options.mode != Mode::Grade) {
        const std::string modeName = modes.updateReferences          ? "--update-references"
                                     : !options.outOfGalleryDir.empty() ? "--check-hints"
                                     : modes.checkMistakes            ? "--check-mistakes"
                                     : modes.determinism              ? "--determinism"
                                                                      : "--write-heatmap-legend";
        const std::pair<bool, const char*> gradingOnly[] = {{options.expect.has_value(), "--expect"},
                                                            {!options.jsonFile.empty(), "--json"},
                                                            {!options.htmlFile.empty(), "--html"},
                                                            {!options.junitFile.empty(), "--junit"}};
        for (const auto& [given, name] : gradingOnly)
            if (given) throw UsageError(std::string(name) + " only applies to grading, not to " + modeName);
    }
    if (options.everyCase && !modes.checkMistakes)
        throw UsageError("--every-case only applies to --check-mistakes and --check-hints");
    if (modes.checkMistakes && !options.cases.empty())
        throw UsageError("--check-mistakes checks the cases each mistake names in 'fails:'; drop --case");
}

} // namespace

Options parseCommandLine(const std::vector<std::string>& arguments) {
    Options options;
    ModeFlags modes;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        std::string option = arguments[i];
        std::optional<std::string> inlineValue;   // --json=FILE
        const std::size_t equals = option.find('=');
        if (option.rfind("--", 0) == 0 && equals != std::string::npos) {
            inlineValue = option.substr(equals + 1);
            option = option.substr(0, equals);
        }
        const OptionSpec& spec = findOption(option);
        std::string value;
        if (!spec.value) {
            if (inlineValue) throw UsageError(option + " takes no value");
        } else if (inlineValue) {
            if (inlineValue->empty()) throw UsageError(option + " needs " + spec.value + " after '='");
            value = *inlineValue;
        } else {
            if (i + 1 >= arguments.size() || arguments[i + 1].rfind("--", 0) == 0)
                throw UsageError(option + " needs " + spec.value);
            value = arguments[++i];
        }
        spec.apply(options, modes, value);
    }
    chooseMode(options, modes);
    return options;
}

std::string usageText() {
    return R"(stoa-grade: renders the labs' graded cases and compares them with the reference images.

usage:
  stoa-grade [--lab NN_name|NN]... [--case NAME]... [options]   grade (every built lab by default)
  stoa-grade --update-references [--lab ...] [--case ...]       write reference images (solutions build)
  stoa-grade --check-mistakes [--lab ...] [--every-case]        check that each planted mistake is caught: it
                                                                fails the cases its fails: line names (graded
                                                                alone; --every-case grades the rest too and
                                                                names the other cases it fails)
  stoa-grade --check-hints DIR [--lab ...] [--every-case]       check that mistakes outside the gallery (DIR/<lab>/mistakes/)
                                                                get no hint naming another cause (the same
                                                                cases as --check-mistakes)
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
