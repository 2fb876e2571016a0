// stoa-grade's command line, lab selection, and the plan of a run.

#include "catch.hpp"

#include "CommandLine.hpp"
#include "LabCatalog.hpp"
#include "LabPlan.hpp"
#include "ReferenceUpdate.hpp"
#include "TempFolder.hpp"

#include <chrono>
#include <filesystem>
#include <sstream>
#include <stdexcept>

using namespace stoa::grader;

namespace {

Options parse(std::vector<std::string> arguments) { return parseCommandLine(arguments); }

// The UsageError's message for `arguments`.
std::string usageError(std::vector<std::string> arguments) {
    try {
        parseCommandLine(arguments);
    } catch (const UsageError& error) {
        return error.what();
    }
    FAIL("no UsageError for the arguments");
    return "";
}

std::vector<LabEntry> someLabs() {
    return {{"01_transforms", "labs/01_transforms/cases.ini"},
            {"02_shading", "labs/02_shading/cases.ini"},
            {"10_crowds", "labs/10_crowds/cases.ini"}};
}

} // namespace

TEST_CASE("parseCommandLine: defaults", "[grader][cli]") {
    Options options = parse({});
    CHECK(options.mode == Mode::Grade);
    CHECK(options.labs.empty());
    CHECK(options.cases.empty());
    CHECK(options.binDir.empty());
    CHECK(options.backend.empty());
    CHECK(options.jsonFile.empty());
    CHECK(options.timeoutSeconds == 0.0);   // from the recorded render times (RenderTimes.hpp)
    CHECK(options.jobs == 1);
    CHECK(options.workDir.empty());
    CHECK_FALSE(options.expect.has_value());
}

TEST_CASE("parseCommandLine: every option, both spellings", "[grader][cli]") {
    Options options = parse({"--lab", "01", "--lab=02_shading", "--case", "orbit_front", "--bin-dir", "build/bin",
                             "--backend=egl", "--json", "out/results.json", "--timeout", "2.5", "--jobs=4",
                             "--work-dir", "/tmp/w", "--expect", "not-attempted"});
    CHECK(options.labs == std::vector<std::string>{"01", "02_shading"});
    CHECK(options.cases == std::vector<std::string>{"orbit_front"});
    CHECK(options.binDir == "build/bin");
    CHECK(options.backend == "egl");
    CHECK(options.jsonFile == "out/results.json");
    CHECK(options.timeoutSeconds == 2.5);
    CHECK(options.jobs == 4);
    CHECK(options.workDir == "/tmp/w");
    CHECK(options.expect == GradeStatus::NotAttempted);
    CHECK(parse({"--expect", "pass"}).expect == GradeStatus::Passed);
}

TEST_CASE("parseCommandLine: modes", "[grader][cli]") {
    CHECK(parse({"--help"}).mode == Mode::Help);
    CHECK(parse({"--lab", "01", "-h"}).mode == Mode::Help);
    CHECK(parse({"--update-references", "--lab", "01", "--case", "a"}).mode == Mode::UpdateReferences);
    CHECK(parse({"--check-mistakes", "--jobs", "2"}).mode == Mode::CheckMistakes);
    CHECK(usageText().find("--update-references") != std::string::npos);
}

TEST_CASE("parseCommandLine: bad usage names the argument and the choices", "[grader][cli]") {
    CHECK(usageError({"--frobnicate"}).find("unknown option '--frobnicate'; the options are --lab, --case") == 0);
    CHECK(usageError({"--backend", "vulkan"}) == "--backend must be osmesa or egl, got 'vulkan'");
    CHECK(usageError({"--expect", "fail"}) == "--expect must be pass or not-attempted, got 'fail'");
    CHECK(usageError({"--timeout", "0"}).find("positive number") != std::string::npos);
    CHECK(usageError({"--timeout", "soon"}).find("'soon'") != std::string::npos);
    CHECK(usageError({"--jobs", "0"}).find("1 to 256") != std::string::npos);
    CHECK(usageError({"--jobs", "2x"}).find("'2x'") != std::string::npos);
    CHECK(usageError({"--lab"}).find("--lab needs a lab") == 0);
    CHECK(usageError({"--lab", "--case", "x"}).find("--lab needs") == 0);
    CHECK(usageError({"--json="}).find("--json needs") == 0);
    CHECK(usageError({"--help=yes"}) == "--help takes no value");
    CHECK(usageError({"01_transforms"}).find("unexpected argument '01_transforms'") == 0);
    CHECK(usageError({"--update-references", "--check-mistakes"}).find("cannot be combined") != std::string::npos);
    CHECK(usageError({"--update-references", "--expect", "pass"}).find("--expect only applies") == 0);
    CHECK(usageError({"--check-mistakes", "--json", "r.json"}).find("--json only applies") == 0);
    CHECK(usageError({"--check-mistakes", "--case", "a"}).find("drop --case") != std::string::npos);
    CHECK(usageError({"--every-case"}).find("--every-case only applies to --check-mistakes and --check-hints") == 0);
    CHECK(parseCommandLine({"--check-hints", "dir", "--every-case"}).everyCase);
    CHECK(parseCommandLine({"--check-mistakes", "--every-case"}).everyCase);
    CHECK_FALSE(parseCommandLine({"--check-mistakes"}).everyCase);
}

TEST_CASE("the options html and junit name report files, for grading only", "[grader][cli][report]") {
    Options options = parseCommandLine({"--html", "out/report.html", "--junit=out/junit.xml"});
    CHECK(options.htmlFile == "out/report.html");
    CHECK(options.junitFile == "out/junit.xml");
    CHECK(parseCommandLine({}).htmlFile.empty());
    CHECK(parseCommandLine({}).junitFile.empty());
    CHECK(usageError({"--html"}).find("--html needs") == 0);
    CHECK(usageError({"--update-references", "--html", "r.html"}).find("--html only applies") == 0);
    CHECK(usageError({"--check-mistakes", "--junit", "j.xml"}).find("--junit only applies") == 0);
}

TEST_CASE("UsageError is an InputError without a file", "[grader][cli]") {
    UsageError error("bad");
    const stoa::InputError& input = error;
    CHECK(input.file().empty());
    CHECK(std::string(input.what()) == "bad");
}

TEST_CASE("selectLabs accepts the folder name, the number and the short name", "[grader][cli]") {
    std::vector<LabEntry> labs = someLabs();
    CHECK(selectLabs(labs, {}).size() == 3);
    CHECK(selectLabs(labs, {"01_transforms"})[0].lab == "01_transforms");
    CHECK(selectLabs(labs, {"02"})[0].lab == "02_shading");
    CHECK(selectLabs(labs, {"10"})[0].lab == "10_crowds");
    CHECK(selectLabs(labs, {"1"})[0].lab == "01_transforms");
    CHECK(selectLabs(labs, {"crowds"})[0].lab == "10_crowds");
    std::vector<LabEntry> two = selectLabs(labs, {"10", "01", "1"});
    REQUIRE(two.size() == 2);
    CHECK(two[0].lab == "01_transforms");
    CHECK(two[1].lab == "10_crowds");
    try {
        selectLabs(labs, {"03"});
        FAIL("no UsageError for an unknown lab");
    } catch (const UsageError& error) {
        CHECK(std::string(error.what()) ==
              "unknown lab '03'; the labs are: 01_transforms, 02_shading, 10_crowds");
    }
}

TEST_CASE("the catalog's paths", "[grader][cli]") {
    CHECK(programName("01_transforms") == "lab01_transforms");
    CHECK(labProgram("/b/bin", "02_shading") == "/b/bin/lab02_shading");
    CHECK(mistakeProgram("/b/bin", "01_transforms", "view_transposed") ==
          "/b/bin/mistakes/01_transforms.view_transposed/lab01_transforms");
    CHECK(referenceImagePath("/src", "01_transforms", "orbit_front") ==
          "/src/autograder/references/01_transforms/orbit_front.png");
    CHECK_FALSE(executableDir().empty());
    CHECK(trackFromInfo("lab=01_transforms\ntrack=solutions\n") == "solutions");
    CHECK(trackFromInfo("track=mistake:view_transposed\r\n") == "mistake:view_transposed");
    CHECK(trackFromInfo("lab=01_transforms\n").empty());
}

TEST_CASE("findLabs and planLabs read the lab folders", "[grader][cli]") {
    stoa::test::TempFolder source;
    source.write("labs/01_transforms/cases.ini",
                 "lab = 01_transforms\ntitle = Transforms\n\n[case orbit_front]\nresolution = 64 32\npoints = 4\n\n"
                 "[case orbit_side]\n");
    source.write("labs/02_shading/cases.ini", "lab = 02_shading\ntitle = Shading\n\n[case blinn]\n");
    source.write("labs/03_meshes/README.md", "no manifest: not a graded lab yet");
    source.write("labs/notes/cases.ini", "not a lab folder name");
    source.write("bin/lab01_transforms", "#!/bin/sh\nexit 0\n", true);

    std::vector<LabEntry> labs = findLabs(source.path());
    REQUIRE(labs.size() == 2);
    CHECK(labs[0].lab == "01_transforms");
    CHECK(labs[1].lab == "02_shading");
    CHECK(findLabs(source.path() / "nowhere").empty());

    std::ostringstream out, err;
    Environment env{source.path(), source.path() / "bin", out, err};
    Options options;
    std::vector<PlannedLab> planned = planLabs(options, env, true);
    REQUIRE(planned.size() == 1);
    CHECK(planned[0].lab == "01_transforms");
    REQUIRE(planned[0].cases.size() == 2);
    CHECK(planned[0].cases[0].width == 64);
    CHECK(planned[0].cases[0].points == 4);
    CHECK(err.str().find("note: lab 02_shading is not built") == 0);

    CHECK(planLabs(options, env, false).size() == 2);

    options.cases = {"orbit_side"};
    planned = planLabs(options, env, false);
    REQUIRE(planned.size() == 1);
    REQUIRE(planned[0].cases.size() == 1);
    CHECK(planned[0].cases[0].name == "orbit_side");

    std::vector<CaseJob> jobs = caseJobs(planned[0], planned[0].program, source.path(), "/work");
    REQUIRE(jobs.size() == 1);
    CHECK(jobs[0].workDir == "/work/01_transforms/orbit_side");
    CHECK(jobs[0].reference == source.path() / "autograder/references/01_transforms/orbit_side.png");

    options.cases = {"orbit_top"};
    try {
        planLabs(options, env, false);
        FAIL("no UsageError for an unknown case");
    } catch (const UsageError& error) {
        std::string message = error.what();
        CHECK(message.find("unknown case 'orbit_top'") == 0);
        CHECK(message.find("01_transforms: orbit_front, orbit_side") != std::string::npos);
    }
}

TEST_CASE("planLabs refuses a lab program older than a student file it was built from", "[grader][cli]") {
    stoa::test::TempFolder source;
    source.write("labs/01_transforms/cases.ini", "lab = 01_transforms\ntitle = Transforms\n\n[case orbit_front]\n");
    source.write("labs/01_transforms/student/transforms.cpp", "// the student's\n");
    source.write("labs/01_transforms/student/cameras.cpp", "// the student's\n");
    source.write("bin/lab01_transforms", "#!/bin/sh\nexit 0\n", true);
    const std::filesystem::path program = source.path() / "bin/lab01_transforms";
    source.write("bin/lab01_transforms.sources",
                 "# what bin/lab01_transforms is built from\nbuild " + (source.path() / "build").string() +
                     "\nsource " + (source.path() / "labs/01_transforms/student/transforms.cpp").string() +
                     "\nsource " + (source.path() / "labs/01_transforms/student/cameras.cpp").string() + "\n");
    // Built after both files were written: graded.
    const auto built = std::filesystem::last_write_time(program);
    std::filesystem::last_write_time(source.path() / "labs/01_transforms/student/transforms.cpp",
                                     built - std::chrono::seconds(60));
    std::filesystem::last_write_time(source.path() / "labs/01_transforms/student/cameras.cpp",
                                     built - std::chrono::seconds(60));
    std::ostringstream out, err;
    Environment env{source.path(), source.path() / "bin", out, err};
    Options options;
    CHECK(planLabs(options, env, true).size() == 1);

    // cameras.cpp edited after the build, and not rebuilt: refused, with the command.
    std::filesystem::last_write_time(source.path() / "labs/01_transforms/student/cameras.cpp",
                                     built + std::chrono::seconds(5));
    std::filesystem::path buildDir;
    const std::vector<std::filesystem::path> newer = staleSources(program, buildDir);
    REQUIRE(newer.size() == 1);
    CHECK(newer[0].filename() == "cameras.cpp");
    CHECK(buildDir == source.path() / "build");
    try {
        planLabs(options, env, true);
        FAIL("a stale program must not be graded");
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        CHECK(message.find("would grade your old code") != std::string::npos);
        CHECK(message.find("lab01_transforms is older than " +
                           (source.path() / "labs/01_transforms/student/cameras.cpp").string()) != std::string::npos);
        CHECK(message.find("transforms.cpp") == std::string::npos);
        CHECK(message.find("cmake --build " + (source.path() / "build").string()) != std::string::npos);
    }
    // Planning without running (the mistakes' check plans, then builds its own) does not look.
    CHECK(planLabs(options, env, false).size() == 1);
}
