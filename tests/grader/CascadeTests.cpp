// Cascades: a lab graded with the student's earlier labs and with their
// solutions counts the run with more points; both runs are reported.

#include "catch.hpp"

#include "BatchGradeJson.hpp"
#include "Cascade.hpp"
#include "Report.hpp"
#include "ResultsJson.hpp"

#include <sstream>

using namespace stoa::grader;

namespace {

GradeResult caseResult(const std::string& lab, const std::string& name, bool passed, double maxPoints,
                       bool cascade) {
    GradeResult r;
    r.lab = lab;
    r.caseName = name;
    r.status = passed ? GradeStatus::Passed : GradeStatus::Failed;
    r.points = passed ? maxPoints : 0.0;
    r.maxPoints = maxPoints;
    r.cascade = cascade;
    return r;
}

// Lab 01 has a mistake, so lab 02's own run fails; with lab 01's solution it passes.
std::vector<GradeResult> brokenFoundation() {
    return {
        caseResult("01_transforms", "orbit_front", false, 2, false),
        caseResult("02_shading", "sun", false, 2, false),
        caseResult("02_shading", "highlights", true, 2, false),
        caseResult("02_shading", "sun", true, 2, true),
        caseResult("02_shading", "highlights", true, 2, true),
    };
}

} // namespace

TEST_CASE("the cascade run counts when it has more points", "[grader][cascade]") {
    std::vector<GradeResult> results = brokenFoundation();
    applyCascadePolicy(results);
    CHECK(results[0].counted);                          // lab 01 has no cascade run
    CHECK_FALSE(results[1].counted);
    CHECK_FALSE(results[2].counted);
    CHECK(results[3].counted);
    CHECK(results[4].counted);

    Totals totals = summarize(results);
    REQUIRE(totals.labs.size() == 2);
    const LabTotals& shading = totals.labs[1];
    CHECK(shading.hasCascade);
    CHECK(shading.ownPoints == 2.0);
    CHECK(shading.cascadePoints == 4.0);
    CHECK(shading.points == 4.0);
    CHECK(shading.maxPoints == 4.0);                    // not 8: only the counted run's cases
    CHECK(shading.statuses.total() == 2);
    CHECK(totals.points == 4.0);
    CHECK(totals.maxPoints == 6.0);
    CHECK_FALSE(totals.labs[0].hasCascade);
}

TEST_CASE("the own run counts on a tie or when it has more points", "[grader][cascade]") {
    std::vector<GradeResult> tie = {caseResult("05_shadows", "sun", true, 3, false),
                                    caseResult("05_shadows", "sun", true, 3, true)};
    applyCascadePolicy(tie);
    CHECK(tie[0].counted);
    CHECK_FALSE(tie[1].counted);

    // Compensating mistakes: the own run passes, the cascade run does not.
    std::vector<GradeResult> own = {caseResult("05_shadows", "sun", true, 3, false),
                                    caseResult("05_shadows", "sun", false, 3, true)};
    applyCascadePolicy(own);
    CHECK(own[0].counted);
    CHECK_FALSE(own[1].counted);
    CHECK(summarize(own).points == 3.0);
}

TEST_CASE("the report and results.json show both runs and add up", "[grader][cascade]") {
    std::vector<GradeResult> results = brokenFoundation();
    applyCascadePolicy(results);
    Totals totals = summarize(results);

    std::ostringstream report;
    printReport(report, results, totals);
    CHECK(report.str().find("sun [cascade]") != std::string::npos);
    CHECK(report.str().find("(not counted)") != std::string::npos);
    CHECK(report.str().find("with your earlier labs 2, with their solutions 4: the higher counts") != std::string::npos);
    CHECK(report.str().find("score: 4 / 6") != std::string::npos);

    std::string json = resultsJson(results, totals, 1.0, "");
    CHECK(json.find("\"02_shading/sun [cascade]\"") != std::string::npos);
    CHECK(json.find("\"not counted\"") != std::string::npos);
    // The uncounted own run of lab 02 scores 0 of 0, so the tests add up to the score.
    JsonValue document = parseJson(json);
    double score = 0.0, maxScore = 0.0;
    for (const JsonValue& test : document.find("tests")->items()) {
        score += test.find("score")->asNumber();
        maxScore += test.find("max_score")->asNumber();
    }
    CHECK(document.find("score")->asNumber() == 4.0);
    CHECK(score == 4.0);
    CHECK(maxScore == 6.0);
}
