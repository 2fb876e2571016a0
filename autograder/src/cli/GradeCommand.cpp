#include "GradeCommand.hpp"

#include "Cascade.hpp"
#include "Grader.hpp"
#include "Hints.hpp"
#include "HtmlReport.hpp"
#include "ProcessContainment.hpp"
#include "JunitReport.hpp"
#include "Report.hpp"
#include "ResultsJson.hpp"
#include "StrayProcesses.hpp"

#include <algorithm>
#include <chrono>
#include <map>
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

int runGrade(const Options& options, const Environment& env) {
    auto start = std::chrono::steady_clock::now();
    std::vector<PlannedLab> labs = planLabs(options, env, true);
    if (labs.empty()) {
        env.err << "stoa-grade: no lab program to run in " << env.binDir.string()
                << ": build the labs first (cmake --build build) or point --bin-dir at them\n";
        return 1;
    }

    std::filesystem::path workDir = makeWorkDir(options.workDir);
    // Once, where the system cannot contain the lab programs as the guide says.
    for (const std::string& note : std::vector<std::string>{networkIsolationNote(), fileConfinementNote()})
        if (!note.empty()) env.err << note << std::endl;
    std::vector<CaseJob> jobs;
    std::map<std::string, std::vector<CaseJob>> cascadeJobs;
    for (const PlannedLab& lab : labs) {
        std::vector<CaseJob> labJobs = caseJobs(lab, lab.program, env.sourceDir, workDir);
        jobs.insert(jobs.end(), labJobs.begin(), labJobs.end());
        if (!lab.cascadeProgram.empty())
            cascadeJobs[lab.lab] = caseJobs(lab, lab.cascadeProgram, env.sourceDir, workDir, true);
    }

    // Read before any lab program runs, for the cascade runs too.
    std::vector<CaseJob> everyJob = jobs;
    for (const auto& [lab, labJobs] : cascadeJobs) everyJob.insert(everyJob.end(), labJobs.begin(), labJobs.end());
    HintGallery gallery = HintGallery::load(everyJob);

    auto printProgress = [&](std::size_t, const GradeResult& result, std::size_t done, std::size_t total) {
        env.err << progressLine(result, done, total) << std::endl;
    };
    std::vector<GradeResult> results = gradeCases(jobs, runSettings(options, env.sourceDir, workDir), options.jobs, printProgress);

    // The cascade runs (Cascade.hpp), for the labs whose own run lost points: one
    // with full marks already counts, as it would on a tie.
    std::vector<CaseJob> cascadeRun;
    std::vector<std::string> fullMarks;
    for (const auto& [lab, labJobs] : cascadeJobs) {
        double points = 0.0, maxPoints = 0.0;
        for (const GradeResult& result : results)
            if (result.lab == lab) {
                points += result.points;
                maxPoints += result.maxPoints;
            }
        if (points >= maxPoints)
            fullMarks.push_back(lab);
        else
            cascadeRun.insert(cascadeRun.end(), labJobs.begin(), labJobs.end());
    }
    if (!fullMarks.empty()) {
        env.err << "cascade runs not needed (full marks on their own):";
        for (const std::string& lab : fullMarks) env.err << " " << lab;
        env.err << std::endl;
    }
    if (!cascadeRun.empty()) {
        env.err << "cascade runs (the lab with the earlier labs' solutions):" << std::endl;
        std::vector<GradeResult> cascadeResults =
            gradeCases(cascadeRun, runSettings(options, env.sourceDir, workDir), options.jobs, printProgress);
        // Each lab's cascade run right after its own, as the reports list them.
        std::vector<CaseJob> orderedJobs;
        std::vector<GradeResult> orderedResults;
        for (const PlannedLab& lab : labs)
            for (const auto* run : {&jobs, &cascadeRun})
                for (std::size_t i = 0; i < run->size(); ++i)
                    if ((*run)[i].lab == lab.lab) {
                        orderedJobs.push_back((*run)[i]);
                        orderedResults.push_back(run == &jobs ? results[i] : cascadeResults[i]);
                    }
        jobs = std::move(orderedJobs);
        results = std::move(orderedResults);
    }
    addHints(results, jobs, gallery, options.jobs);
    applyCascadePolicy(results);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // Each case's leftovers were killed as it ended; this is the last look before
    // any report is written: nothing a lab program started may be running then.
    if (std::size_t strays = killStrayProcesses())
        env.err << "stoa-grade: killed " << strays << " more processes the lab programs had left running\n";

    Totals totals = summarize(results);
    env.out << "\n";
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

    // The folder is named only when it holds a picture (after a compile error it holds none).
    bool rendered = std::any_of(results.begin(), results.end(), [](const GradeResult& result) {
        return !result.renderedImage.empty() || !result.heatMapImage.empty();
    });
    bool keep = !options.workDir.empty() || std::any_of(results.begin(), results.end(), worthKeeping);
    if (keep && rendered) {
        env.out << "rendered images and heat maps: " << workDir.string() << "\n";
    } else if (options.workDir.empty()) {
        std::error_code ignored;
        std::filesystem::remove_all(workDir, ignored);
    }

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
