#pragma once
// The outline every mode of stoa-grade follows: plan the cases, read the hint
// gallery before any lab program runs, run the cases in parallel with a
// progress line each, add hints, report, and then keep or remove the work
// folder. Grading, --check-mistakes, --check-hints, --determinism and
// --update-references differ only in what they plan and how they report.
//
//   GradingRun run(options, env);
//   std::vector<CaseOutcome> outcomes = run.grade(plannedOutcomes(caseJobs(...)));
//   run.addHints(outcomes);
//   ... report resultsOf(outcomes) ...
//   run.finish(keepImages);

#include "CaseOutcome.hpp"
#include "GradeOptions.hpp"
#include "Hints.hpp"
#include "LabPlan.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

/// True, with a message on env.err, when `labs` (planned with their programs
/// required) is empty: no lab program is built in env.binDir. `howToBuild`
/// ends the message ("build the labs first (cmake --build build)").
bool noProgramToRun(const std::vector<PlannedLab>& labs, const Environment& env, const std::string& howToBuild);

class GradingRun {
public:
    /// Makes the work folder (--work-dir, or a new temporary one) and the run's
    /// settings (limits, backend, what the lab programs may touch).
    GradingRun(const Options& options, const Environment& env);

    const std::filesystem::path& workDir() const { return m_workDir; }
    const RunSettings& settings() const { return m_settings; }

    /// Reads the gallery images of `outcomes`' cases now (grade() reads those it
    /// has not read yet): call it before the first grade() for cases graded later.
    void readGallery(const std::vector<CaseOutcome>& outcomes);
    /// Grades every planned case, `--jobs` at a time, printing a progress line
    /// as each ends; returns them graded, in the same order.
    std::vector<CaseOutcome> grade(std::vector<CaseOutcome> planned);
    /// Renders every planned case without grading it (RenderOutcome in `render`),
    /// `--jobs` at a time, printing a progress line as each ends.
    std::vector<CaseOutcome> render(std::vector<CaseOutcome> planned);
    /// The hints of the failed cases, from the gallery read before they ran.
    void addHints(std::vector<CaseOutcome>& outcomes) const;

    /// With `keepImages`, says where the images are ("WHAT: FOLDER[UNDER]");
    /// otherwise removes the work folder, unless --work-dir named it.
    void finish(bool keepImages, const std::string& what = "rendered images and heat maps",
                const std::string& under = "");

private:
    void progress(const std::string& line) const;   // a case done: a line, or the one line rewritten
    void endProgress() const;
    const Options& m_options;
    const Environment& m_env;
    std::filesystem::path m_workDir;
    RunSettings m_settings;
    HintGallery m_gallery;
};

} // namespace stoa::grader
