#include "GradingRun.hpp"

#include "Grader.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <string>

namespace stoa::grader {

namespace {

std::vector<CaseJob> jobsOf(const std::vector<CaseOutcome>& outcomes) {
    std::vector<CaseJob> jobs;
    jobs.reserve(outcomes.size());
    for (const CaseOutcome& outcome : outcomes) jobs.push_back(outcome.job);
    return jobs;
}

// The lab page's "How fast" section, for a case that was still computing when
// its limit ran out; "" when the page has none (a pointer is right or absent).
std::string howFastSection(const std::filesystem::path& sourceDir, const std::string& lab) {
    const std::filesystem::path page = sourceDir / "docs" / "labs" / (lab + ".md");
    std::ifstream in(page);
    for (std::string line; std::getline(in, line);)
        if (line == "## How fast") return "docs/labs/" + lab + ".md, \"How fast\"";
    return "";
}

} // namespace

void GradingRun::progress(const std::string& line) const {
    if (m_env.progressInPlace) {
        m_env.err << "\r\033[K" << line << std::flush;   // over the line before
    } else {
        m_env.err << line << std::endl;
    }
}

void GradingRun::endProgress() const {
    if (m_env.progressInPlace) m_env.err << "\r\033[K" << std::flush;
}

bool noProgramToRun(const std::vector<PlannedLab>& labs, const Environment& env, const std::string& howToBuild) {
    if (!labs.empty()) return false;
    env.err << "stoa-grade: no lab program to run in " << env.binDir.string() << ": " << howToBuild << "\n";
    return true;
}

GradingRun::GradingRun(const Options& options, const Environment& env)
    : m_options(options), m_env(env), m_workDir(makeWorkDir(options.workDir)),
      m_settings(runSettings(options, env.sourceDir, m_workDir)) {}

void GradingRun::readGallery(const std::vector<CaseOutcome>& outcomes) { m_gallery.add(jobsOf(outcomes)); }

std::vector<CaseOutcome> GradingRun::grade(std::vector<CaseOutcome> planned) {
    if (planned.empty()) return planned;
    const std::vector<CaseJob> jobs = jobsOf(planned);
    m_gallery.add(jobs);   // before any of them runs
    std::vector<GradeResult> results =
        gradeCases(jobs, m_settings, m_options.jobs, [&](std::size_t index, const GradeResult& result, std::size_t done,
                                                         std::size_t total) {
            progress(progressLine(result, done, total, planned[index].label));
        });
    endProgress();
    std::map<std::string, std::string> howFast;   // lab -> its section, read once
    for (GradeResult& result : results) {
        if (!result.busyWhenStopped) continue;
        if (!howFast.count(result.lab)) howFast[result.lab] = howFastSection(m_env.sourceDir, result.lab);
        if (!howFast[result.lab].empty()) result.reason += "; how fast it should be: " + howFast[result.lab];
    }
    for (std::size_t i = 0; i < planned.size(); ++i) planned[i].result = std::move(results[i]);
    return planned;
}

std::vector<CaseOutcome> GradingRun::render(std::vector<CaseOutcome> planned) {
    std::mutex progressMutex;
    std::size_t done = 0;
    forEachInParallel(planned.size(), m_options.jobs, [&](std::size_t i) {
        CaseOutcome& outcome = planned[i];
        outcome.render = renderCase(outcome.job, m_settings);
        std::lock_guard<std::mutex> lock(progressMutex);
        progress("[" + std::to_string(++done) + "/" + std::to_string(planned.size()) + "] " +
                 (outcome.label.empty() ? "" : outcome.label + ": ") + outcome.job.lab + "/" + outcome.job.spec.name +
                 " ... " + (outcome.render.rendered ? "rendered" : statusName(outcome.render.status)));
    });
    endProgress();
    return planned;
}

void GradingRun::addHints(std::vector<CaseOutcome>& outcomes) const {
    grader::addHints(outcomes, m_gallery, m_options.jobs);
}

void GradingRun::finish(bool keepImages, const std::string& what, const std::string& under) {
    if (keepImages) {
        m_env.out << what << ": " << m_workDir.string() << under << "\n";
    } else if (m_options.workDir.empty()) {
        std::error_code ignored;
        std::filesystem::remove_all(m_workDir, ignored);
    }
}

} // namespace stoa::grader
