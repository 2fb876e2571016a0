// Adding results up, the terminal report, the hints, and --expect.

#include "catch.hpp"

#include "GradeCommand.hpp"
#include "Grader.hpp"
#include "Report.hpp"

#include <sstream>

using namespace stoa::grader;

namespace {

GradeResult result(const std::string& lab, const std::string& name, GradeStatus status, double points,
                   double maxPoints, const std::string& reason = "") {
    GradeResult r;
    r.lab = lab;
    r.caseName = name;
    r.status = status;
    r.points = points;
    r.maxPoints = maxPoints;
    r.reason = reason;
    return r;
}

std::vector<GradeResult> sample() {
    return {
        result("01_transforms", "orbit_front", GradeStatus::Passed, 10, 10, "0.00% pixels off (max 2, mean 0.01)"),
        result("01_transforms", "orbit_side", GradeStatus::Failed, 0, 5, "4.20% pixels off (max 255, mean 9.3)"),
        result("01_transforms", "fly", GradeStatus::Error, 0, 2.5, "crashed with SIGSEGV (segmentation fault)"),
        result("02_shading", "blinn", GradeStatus::NotAttempted, 0, 10, "not implemented: shade()"),
        result("02_shading", "ambient", GradeStatus::NotAttempted, 0, 5, "not implemented: shade()"),
    };
}

} // namespace

TEST_CASE("summarize adds points and counts statuses per lab and overall", "[grader][report]") {
    Totals totals = summarize(sample());
    REQUIRE(totals.labs.size() == 2);
    CHECK(totals.labs[0].lab == "01_transforms");
    CHECK(totals.labs[0].points == 10);
    CHECK(totals.labs[0].maxPoints == 17.5);
    CHECK(totals.labs[0].statuses[GradeStatus::Passed] == 1);
    CHECK(totals.labs[0].statuses[GradeStatus::Failed] == 1);
    CHECK(totals.labs[0].statuses[GradeStatus::Error] == 1);
    CHECK_FALSE(totals.labs[0].nothingAttempted());
    CHECK(totals.labs[1].maxPoints == 15);
    CHECK(totals.labs[1].nothingAttempted());
    CHECK(totals.points == 10);
    CHECK(totals.maxPoints == 32.5);
    CHECK(totals.statuses.total() == 5);
    CHECK(totals.statuses.describe() == "1 passed, 1 failed, 2 not attempted, 1 error");

    Totals empty = summarize({});
    CHECK(empty.labs.empty());
    CHECK(empty.maxPoints == 0);
    CHECK(empty.statuses.describe() == "no cases");
}

TEST_CASE("statusName and formatPoints read as a person writes them", "[grader][report]") {
    CHECK(std::string(statusName(GradeStatus::NotAttempted)) == "not attempted");
    CHECK(std::string(statusName(GradeStatus::NoReference)) == "no reference");
    CHECK(formatPoints(10) == "10");
    CHECK(formatPoints(2.5) == "2.5");
    CHECK(formatPoints(0.25) == "0.25");
    CHECK(formatPoints(0) == "0");
    CHECK(formatPoints(1.0 / 3.0) == "0.33");
}

TEST_CASE("printReport shows the table, details, totals and the score", "[grader][report]") {
    std::vector<GradeResult> results = sample();
    results[1].renderedImage = "/tmp/w/01_transforms/orbit_side/rendered.png";
    results[1].heatMapImage = "/tmp/w/01_transforms/orbit_side/heatmap.png";
    results[2].programOutput = "line one\nSegmentation fault\n";
    std::ostringstream out;
    printReport(out, results, summarize(results));
    std::string text = out.str();
    CHECK(text.rfind("lab", 0) == 0);
    CHECK(text.find("orbit_side") != std::string::npos);
    CHECK(text.find("4.20% pixels off") != std::string::npos);
    CHECK(text.find("heat map:  /tmp/w/01_transforms/orbit_side/heatmap.png") != std::string::npos);
    CHECK(text.find("yours:     /tmp/w/01_transforms/orbit_side/rendered.png") != std::string::npos);
    CHECK(text.find("| Segmentation fault") != std::string::npos);
    CHECK(text.find("01_transforms  10 / 17.5 points") != std::string::npos);
    CHECK(text.find("total") != std::string::npos);
    CHECK(text.substr(text.size() - 17) == "score: 10 / 32.5\n");
}

TEST_CASE("printReport puts a known-mistake hint under the failed case's row", "[grader][report][hint]") {
    std::vector<GradeResult> results = sample();
    results[1].hint = "The view matrix is transposed.";
    results[1].hintDocs = "docs/labs/01_transforms.md#the-view-matrix";
    results[1].hintMistake = "view_transposed";
    std::ostringstream out;
    printReport(out, results, summarize(results));
    std::string text = out.str();
    std::string line = "               hint: looks like the known mistake 'view_transposed': The view matrix is "
                       "transposed.\n";
    std::size_t row = text.find("orbit_side");
    REQUIRE(row != std::string::npos);
    CHECK(text.find(line) == text.find('\n', row) + 1);   // the line right after the row, wrapped
    CHECK(hintLine(results[0]).empty());
    results[1].hintDocs.clear();
    CHECK(hintLine(results[1], 2) == "  hint: looks like the known mistake 'view_transposed': The view matrix is "
                                     "transposed.");
    results[1].metrics = CompareMetrics{0.04, 9.3, 255, 0.21};
    results[1].hintDistance = 0.003;
    CHECK(hintLine(results[1]) == "hint: looks like the known mistake 'view_transposed' (FLIP mean 0.003 from its "
                                  "picture, 0.210 from the reference): The view matrix is transposed.");
}

TEST_CASE("printReport: metric columns with thresholds, no cut words, details of what did not pass",
          "[grader][report]") {
    std::vector<GradeResult> results = sample();
    for (GradeResult& r : results) {
        r.maxBadFraction = 0.002;
        r.maxFlipMean = 0.05;
    }
    results[0].metrics = CompareMetrics{0.0, 0.01, 2, 0.0};
    results[1].metrics = CompareMetrics{0.042, 9.3, 255, 0.2134};
    results[1].difference = "differs in 4.2% of the pixels, most of them in the top left (90% of them)";
    results[0].reason = std::string(120, 'x');   // a passed case's long reason is not detailed
    results[2].reason = "crashed with SIGSEGV (segmentation fault) while the program was drawing the third of its "
                        "many frames";
    std::ostringstream out;
    printReport(out, results, summarize(results));
    std::string text = out.str();
    CHECK(text.find("differing pixels") != std::string::npos);
    CHECK(text.find("pass: <= 0.20%") != std::string::npos);
    CHECK(text.find("pass: <= 0.050") != std::string::npos);
    CHECK(text.find("4.20%") != std::string::npos);
    CHECK(text.find("0.213") != std::string::npos);
    CHECK(text.find("xxxxxxxx") == std::string::npos);
    CHECK(text.find("where: differs in 4.2% of the pixels") != std::string::npos);
    CHECK(text.find("(see the details below)") != std::string::npos);
    CHECK(text.find("  01_transforms/fly: error: crashed with SIGSEGV") != std::string::npos);
    CHECK(text.find("01_transforms/orbit_front") == std::string::npos);   // passed: no details
    CHECK(text.find("...") == std::string::npos);                         // nothing cut
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) CHECK(line.size() <= 100);
}

TEST_CASE("printReport: one line per lab where nothing was attempted, one error per lab", "[grader][report]") {
    std::vector<GradeResult> results = sample();
    for (int i = 0; i < 3; ++i) {
        GradeResult r = result("03_meshes", "case" + std::to_string(i), GradeStatus::Error, 0, 2,
                               "shader compile error: textures.glsl:7: syntax error");
        r.programOutput = "0:7(10): error: syntax error, unexpected '}'\n";
        results.push_back(r);
    }
    std::ostringstream out;
    printReport(out, results, summarize(results));
    std::string text = out.str();
    CHECK(text.find("02_shading  ") != std::string::npos);
    CHECK(text.find("blinn") == std::string::npos);   // collapsed into the lab's line
    CHECK(text.find("(2 cases)") != std::string::npos);
    CHECK(text.find("start with docs/labs/02_shading.md") != std::string::npos);
    std::size_t first = text.find("syntax error, unexpected");
    REQUIRE(first != std::string::npos);
    CHECK(text.find("syntax error, unexpected", first + 1) == std::string::npos);   // printed once
    CHECK(text.find("03_meshes (3 cases: case0, case1, case2): error: shader compile error") != std::string::npos);
}

TEST_CASE("hints point at the docs of labs where nothing was attempted", "[grader][report]") {
    std::vector<std::string> lines = hints(summarize(sample()));
    REQUIRE(lines.size() == 1);
    CHECK(lines[0] == "lab 02_shading: nothing attempted yet -- start with docs/labs/02_shading.md");
}

TEST_CASE("unmetExpectations: with --expect, every case must have the status", "[grader][report]") {
    std::vector<GradeResult> stubs = {result("01", "a", GradeStatus::NotAttempted, 0, 1),
                                      result("01", "b", GradeStatus::NotAttempted, 0, 1)};
    CHECK(allHaveStatus(stubs, GradeStatus::NotAttempted));
    CHECK(unmetExpectations(stubs, GradeStatus::NotAttempted).empty());
    CHECK_FALSE(allHaveStatus({}, GradeStatus::Passed));
    CHECK(unmetExpectations({}, GradeStatus::Passed) == std::vector<std::string>{"no case was graded"});

    std::vector<std::string> unmet = unmetExpectations(sample(), GradeStatus::Passed);
    REQUIRE(unmet.size() == 4);
    CHECK(unmet[0] == "01_transforms/orbit_side is failed: 4.20% pixels off (max 255, mean 9.3)");
}

TEST_CASE("progressLine", "[grader][report]") {
    GradeResult r = result("01_transforms", "orbit_front", GradeStatus::Passed, 1, 1);
    r.seconds = 0.84;
    CHECK(progressLine(r, 3, 12) == "[3/12] 01_transforms/orbit_front ... passed (0.8 s)");
    CHECK(progressLine(r, 3, 12, "mistake m") == "[3/12] mistake m: 01_transforms/orbit_front ... passed (0.8 s)");
}

TEST_CASE("a lab that waits for an earlier lab's stub points to that lab", "[grader][report]") {
    // Lab 07 draws with lab 01's cameras: its program names the stub's lab
    // (NotImplemented::describe()), and the one-line row sends the student there.
    const std::vector<GradeResult> results = {
        result("07_picking", "raycast_front", GradeStatus::NotAttempted, 0, 3,
               "not implemented: OrbitCamera::eyePosition() (lab 01_transforms)"),
        result("07_picking", "id_buffer", GradeStatus::NotAttempted, 0, 2,
               "not implemented: OrbitCamera::eyePosition() (lab 01_transforms)"),
        result("06_culling", "field_walk", GradeStatus::NotAttempted, 0, 2, "not implemented: meshBoundingSphere()"),
    };
    std::ostringstream out;
    printReport(out, results, summarize(results));
    const std::string text = out.str();
    // Lab 01 has no line here to name its stub: lab 07's does, on a line of its own when it does not fit.
    CHECK(text.find("waits for lab 01_transforms") != std::string::npos);
    CHECK(text.find("OrbitCamera::eyePosition() is a stub there\n") != std::string::npos);
    CHECK(text.find("start with docs/labs/06_culling.md") != std::string::npos);
    CHECK(text.find("start with docs/labs/07_picking.md") == std::string::npos);
    // Lab 01 is not in this report: the next step is still where lab 07 waits.
    CHECK(text.find("\nnext: lab 01_transforms, docs/labs/01_transforms.md\nscore: 0 / 7\n") != std::string::npos);
}

TEST_CASE("printReport: a lab where nothing was attempted names the stub its first case ran into",
          "[grader][report]") {
    const std::vector<GradeResult> results = {
        result("09_ssao", "column_bases_raw", GradeStatus::NotAttempted, 0, 2,
               "not implemented: blurAmbientOcclusion (/home/student/stoa/labs/09_ssao/student/ssao.glsl:67)"),
        result("09_ssao", "statue_final", GradeStatus::NotAttempted, 0, 2,
               "not implemented: blurAmbientOcclusion (/home/student/stoa/labs/09_ssao/student/ssao.glsl:67)"),
        result("06_culling", "field_walk", GradeStatus::NotAttempted, 0, 2, "not implemented: meshBoundingSphere()"),
    };
    std::ostringstream out;
    printReport(out, results, summarize(results));
    const std::string text = out.str();
    // On a line of its own under the lab's, the file without its folders: the lines stay short.
    CHECK(text.find("start with docs/labs/09_ssao.md\n") != std::string::npos);
    CHECK(text.find("first stub: blurAmbientOcclusion (ssao.glsl:67)\n") != std::string::npos);
    // Only the first lab to start with has its stub's line: a fresh clone's report fits a screen.
    CHECK(text.find("first stub: meshBoundingSphere()") == std::string::npos);
    CHECK(text.find("next: lab 09_ssao, docs/labs/09_ssao.md\n") != std::string::npos);
    CHECK(text.find("/home/student") == std::string::npos);
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) CHECK(line.size() <= 100);
}

TEST_CASE("printReport: a fresh clone (every lab a stub, every cascade run too) fits one screen", "[grader][report]") {
    // Eleven labs as the README's main command grades them on a fresh clone:
    // each lab's own run not attempted (lab 02 and others wait for lab 01's
    // cameras), and each cascade run, with the earlier labs' solutions, not
    // attempted either (the lab's own stubs). Nothing but one line per lab,
    // the total, the next step and the score.
    std::vector<GradeResult> results;
    const std::vector<std::string> labs = {"01_transforms", "02_shading", "03_meshes", "04_normal_mapping",
                                           "05_shadows", "06_culling", "07_picking", "08_deferred",
                                           "09_ssao", "10_crowds", "11_editor"};
    for (const std::string& lab : labs) {
        const bool waits = lab == "02_shading" || lab == "07_picking" || lab == "11_editor";
        for (int i = 0; i < 8; ++i) {
            const std::string name = "case_with_a_long_name_" + std::to_string(i);
            results.push_back(result(lab, name, GradeStatus::NotAttempted, 0, 2,
                                     waits ? "not implemented: eyePosition(OrbitState) (lab 01_transforms)"
                                           : "not implemented: firstStubOf" + lab.substr(3) + "()"));
            if (lab == "01_transforms") continue;
            GradeResult cascade = result(lab, name, GradeStatus::NotAttempted, 0, 2,
                                         "not implemented: ownStubOf" + lab.substr(3) + "()");
            cascade.cascade = true;
            cascade.counted = false;
            results.push_back(cascade);
        }
    }
    std::ostringstream out;
    printReport(out, results, summarize(results));
    const std::string text = out.str();
    INFO(text);
    CHECK(std::count(text.begin(), text.end(), '\n') <= 20);
    CHECK(text.find("[cascade]") == std::string::npos);
    CHECK(text.find("with your earlier labs") == std::string::npos);
    CHECK(text.find("details") == std::string::npos);
    CHECK(text.find("first stub: firstStubOftransforms()\n") != std::string::npos);
    CHECK(text.find("next: lab 01_transforms, docs/labs/01_transforms.md\nscore: 0 / 176\n") != std::string::npos);
}

TEST_CASE("printReport: a cascade run that earned points keeps its rows and its line under the lab",
          "[grader][report]") {
    // Lab 02 done, lab 01 not: its own run waits for lab 01, its cascade run passes.
    GradeResult own = result("02_shading", "sun", GradeStatus::NotAttempted, 0, 2,
                             "not implemented: eyePosition(OrbitState) (lab 01_transforms)");
    own.counted = false;
    GradeResult cascade = result("02_shading", "sun", GradeStatus::Passed, 2, 2, "");
    cascade.cascade = true;
    const std::vector<GradeResult> results = {own, cascade};
    std::ostringstream out;
    printReport(out, results, summarize(results));
    const std::string text = out.str();
    INFO(text);
    CHECK(text.find("sun [cascade]") != std::string::npos);
    CHECK(text.find("with your earlier labs 0, with their solutions 2: the higher counts") != std::string::npos);
}
