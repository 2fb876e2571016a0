#include "GradeCommand.hpp"

#include "Cascade.hpp"
#include "Grader.hpp"
#include "GradingRun.hpp"
#include "Hints.hpp"
#include "HtmlReport.hpp"
#include "ProcessContainment.hpp"
#include "JunitReport.hpp"
#include "Report.hpp"
#include "ResultsJson.hpp"
#include "StrayProcesses.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <map>
#include <ostream>
#include <sstream>

namespace stoa::grader {

namespace {

// The text Gradescope shows above the tests: the score, the counts, the hints.
std::string summaryText(const Totals& totals) {
    std::ostringstream text;
    text << "score: " << formatPoints(totals.points) << " / " << formatPoints(totals.maxPoints) << " ("
         << totals.statuses.describe() << ")\n";
    for (const std::string& hint : hints(totals)) text << hint << "\n";
    return text.str();
}

bool worthKeeping(const GradeResult& result) {
    return result.status == GradeStatus::Failed || result.status == GradeStatus::Error;
}

} // namespace

std::vector<std::string> unmetExpectations(const std::vector<GradeResult>& results, GradeStatus expected) {
    std::vector<std::string> lines;
    if (results.empty()) lines.push_back("no case was graded");
    for (const GradeResult& result : results)
        if (result.status != expected)
            lines.push_back(result.fullName() + " is " + statusName(result.status) +
                            (result.reason.empty() ? "" : ": " + result.reason));
    return lines;
}

namespace {

// The cases of the selected labs, and those of their cascade runs (Cascade.hpp).
struct GradePlan {
    std::vector<CaseOutcome> own;
    std::vector<CaseOutcome> cascades;
};

GradePlan planGrade(const std::vector<PlannedLab>& labs, const Environment& env, const std::filesystem::path& workDir) {
    GradePlan plan;
    for (const PlannedLab& lab : labs) {
        for (CaseOutcome& outcome : plannedOutcomes(caseJobs(lab, lab.program, env.sourceDir, workDir)))
            plan.own.push_back(std::move(outcome));
        if (lab.cascadeProgram.empty()) continue;
        for (CaseOutcome& outcome : plannedOutcomes(caseJobs(lab, lab.cascadeProgram, env.sourceDir, workDir, true)))
            plan.cascades.push_back(std::move(outcome));
    }
    return plan;
}

// The cascade runs worth running: those of the labs whose own run lost points
// (one with full marks already counts, as it would on a tie).
std::vector<CaseOutcome> cascadesNeeded(const std::vector<CaseOutcome>& own, std::vector<CaseOutcome> cascades,
                                        std::ostream& err) {
    std::map<std::string, std::pair<double, double>> points;   // lab -> earned, possible
    for (const CaseOutcome& outcome : own) {
        points[outcome.job.lab].first += outcome.result.points;
        points[outcome.job.lab].second += outcome.result.maxPoints;
    }
    std::vector<std::string> fullMarks;
    std::vector<CaseOutcome> needed;
    for (CaseOutcome& outcome : cascades) {
        const auto [earned, possible] = points[outcome.job.lab];
        if (earned < possible) {
            needed.push_back(std::move(outcome));
        } else if (std::find(fullMarks.begin(), fullMarks.end(), outcome.job.lab) == fullMarks.end()) {
            fullMarks.push_back(outcome.job.lab);
        }
    }
    if (!fullMarks.empty()) {
        err << "cascade runs not needed (full marks on their own):";
        for (const std::string& lab : fullMarks) err << " " << lab;
        err << std::endl;
    }
    if (!needed.empty()) err << "cascade runs (the lab with the earlier labs' solutions):" << std::endl;
    return needed;
}

// Each lab's own cases, then its cascade run's, in the order the labs were planned.
std::vector<CaseOutcome> inReportOrder(const std::vector<PlannedLab>& labs, std::vector<CaseOutcome> own,
                                       std::vector<CaseOutcome> cascaded) {
    std::map<std::string, std::size_t> rank;
    for (const PlannedLab& lab : labs) rank.emplace(lab.lab, rank.size());
    own.insert(own.end(), std::make_move_iterator(cascaded.begin()), std::make_move_iterator(cascaded.end()));
    std::stable_sort(own.begin(), own.end(), [&](const CaseOutcome& a, const CaseOutcome& b) {
        return rank[a.job.lab] < rank[b.job.lab];
    });
    return own;
}

void writeReports(const Options& options, const Environment& env, const std::vector<GradeResult>& results,
                  double seconds) {
    Totals totals = summarize(results);
    if (!env.progressInPlace) env.out << "\n";   // after the progress lines, where they stay
    printReport(env.out, results, totals);   // a lab where nothing was attempted says where to start
    if (!options.jsonFile.empty()) {
        writeResultsJson(options.jsonFile, results, totals, seconds, summaryText(totals));
        env.out << "wrote " << options.jsonFile.string() << "\n";
    }
    if (!options.htmlFile.empty()) {
        HtmlReportOptions html;
        html.docsBaseUrl = "file://" + std::filesystem::absolute(env.sourceDir).string() + "/";
        html.siteDir = findDocsSite(env.sourceDir, env.binDir);
        writeHtmlReport(options.htmlFile, results, totals, html);
        env.out << "wrote " << options.htmlFile.string() << "\n";
    }
    if (!options.junitFile.empty()) {
        writeJunitXml(options.junitFile, results);
        env.out << "wrote " << options.junitFile.string() << "\n";
    }
}

// Keep the work folder when it holds a picture worth a look: a failed or broken
// case's, or any when --work-dir named it (after a compile error it holds none).
bool imagesWorthKeeping(const Options& options, const std::vector<GradeResult>& results) {
    bool rendered = std::any_of(results.begin(), results.end(), [](const GradeResult& result) {
        return !result.renderedImage.empty() || !result.heatMapImage.empty();
    });
    return rendered && (!options.workDir.empty() || std::any_of(results.begin(), results.end(), worthKeeping));
}

} // namespace

int runGrade(const Options& options, const Environment& env) {
    auto start = std::chrono::steady_clock::now();
    std::vector<PlannedLab> labs = planLabs(options, env, true);
    if (noProgramToRun(labs, env, "build the labs first (cmake --build build) or point --bin-dir at them")) return 1;
    GradingRun run(options, env);
    // Once, where the system cannot contain the lab programs as the guide says.
    for (const std::string& note : std::vector<std::string>{networkIsolationNote(), fileConfinementNote()})
        if (!note.empty()) env.err << note << std::endl;

    GradePlan plan = planGrade(labs, env, run.workDir());
    run.readGallery(plan.cascades);   // before any lab program runs
    std::vector<CaseOutcome> own = run.grade(std::move(plan.own));
    std::vector<CaseOutcome> cascaded = run.grade(cascadesNeeded(own, std::move(plan.cascades), env.err));
    std::vector<CaseOutcome> outcomes = inReportOrder(labs, std::move(own), std::move(cascaded));
    run.addHints(outcomes);
    std::vector<GradeResult> results = resultsOf(outcomes);
    applyCascadePolicy(results);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // Each case's leftovers were killed as it ended; this is the last look before
    // any report is written: nothing a lab program started may be running then.
    if (std::size_t strays = killStrayProcesses())
        env.err << "stoa-grade: killed " << strays << " more processes the lab programs had left running\n";

    writeReports(options, env, results, seconds);
    run.finish(imagesWorthKeeping(options, results));

    if (options.expect) {
        std::vector<std::string> unmet = unmetExpectations(results, *options.expect);
        if (!unmet.empty()) {
            env.err << "stoa-grade: expected every case to be " << statusName(*options.expect) << ", but:\n";
            for (const std::string& line : unmet) env.err << "  " << line << "\n";
            return 1;
        }
    }
    return 0;
}

} // namespace stoa::grader
