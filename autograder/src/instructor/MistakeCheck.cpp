#include "MistakeCheck.hpp"

#include "Grader.hpp"
#include "GradingRun.hpp"
#include "Hints.hpp"
#include "Report.hpp"

#include <algorithm>
#include <ostream>

namespace stoa::grader {

namespace {

struct MistakeRun {
    MistakeFile mistake;
    std::string manifestProblem;   // a fails: case the manifest does not have
    std::size_t firstJob = 0;
    std::size_t jobCount = 0;
};

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& word : words) text += (text.empty() ? "" : " ") + word;
    return text;
}

std::string padded(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

// Each case of the mistake's fails: line that was not graded, or did not fail, with why.
std::vector<std::string> notFailedAsListed(const MistakeFile& mistake, const std::vector<GradeResult>& results) {
    std::vector<std::string> problems;
    for (const std::string& name : mistake.fails) {
        auto result = std::find_if(results.begin(), results.end(),
                                   [&](const GradeResult& entry) { return entry.caseName == name; });
        if (result == results.end())
            problems.push_back(name + " was not graded");
        else if (result->status != GradeStatus::Failed)
            problems.push_back(name + " " + (result->status == GradeStatus::Passed ? std::string(statusName(GradeStatus::Passed))
                                             : std::string("is ") + statusName(result->status) + ": " + result->reason));
    }
    return problems;
}

// The failed cases that the mistake's fails: line does not name.
std::vector<std::string> alsoFailed(const MistakeFile& mistake, const std::vector<GradeResult>& results) {
    std::vector<std::string> names;
    for (const GradeResult& result : results)
        if (result.status == GradeStatus::Failed &&
            std::find(mistake.fails.begin(), mistake.fails.end(), result.caseName) == mistake.fails.end())
            names.push_back(result.caseName);
    return names;
}

} // namespace

MistakeVerdict judgeOutOfGallery(const MistakeFile& mistake, const std::vector<GradeResult>& results) {
    std::vector<std::string> problems = notFailedAsListed(mistake, results), wrong, right;
    const std::vector<std::string> alsoFails = alsoFailed(mistake, results);
    for (const GradeResult& result : results) {
        if (!result.hasHint()) continue;
        // Right only where the entry's hint lists this cause: hint-ok says so, and the
        // hint names the file the cause is in.
        bool listed = std::find(mistake.hintOk.begin(), mistake.hintOk.end(), result.hintMistake) !=
                      mistake.hintOk.end();
        bool namesFile = result.hint.find(mistake.file) != std::string::npos;
        if (listed && namesFile)
            right.push_back(result.caseName + " -> " + result.hintMistake);
        else
            wrong.push_back(result.caseName + " -> " + result.hintMistake +
                            (listed ? " (whose hint does not list " + mistake.file + ")" : ""));
    }
    MistakeVerdict verdict;
    verdict.caught = problems.empty() && wrong.empty();
    if (!wrong.empty()) verdict.detail = "WRONG HINT: " + joined(wrong);
    else if (!right.empty()) verdict.detail = "hint lists its cause: " + joined(right);
    else verdict.detail = "silent (no hint)";
    if (!problems.empty()) {
        std::string text;
        for (std::size_t i = 0; i < problems.size(); ++i) text += (i ? "; " : "") + problems[i];
        verdict.detail += "; NOT as its fails: line says: " + text;
    }
    if (!alsoFails.empty()) verdict.detail += " (also fails " + joined(alsoFails) + ")";
    return verdict;
}

MistakeVerdict judgeMistake(const MistakeFile& mistake, const std::vector<GradeResult>& results) {
    std::vector<std::string> problems = notFailedAsListed(mistake, results);
    const std::vector<std::string> alsoFails = alsoFailed(mistake, results);

    // The hint must name the mistake on at least one case it fails: that is what
    // a student with this bug would read.
    bool hintNamesIt = false;
    std::vector<std::string> hintNotes;
    for (const std::string& name : mistake.fails) {
        auto result = std::find_if(results.begin(), results.end(),
                                   [&](const GradeResult& entry) { return entry.caseName == name; });
        if (result == results.end() || result->status != GradeStatus::Failed) continue;
        if (result->hintMistake == mistake.name) hintNamesIt = true;
        else if (!result->propertyCheck)
            hintNotes.push_back(name + ": " + (result->hasHint() ? "hint names " + result->hintMistake : "no hint"));
    }
    // A mistake that fails property checks only has no picture to match: each check's own
    // message says what does not hold. One that also fails a picture case needs its hint there.
    const bool checksOnly = std::all_of(mistake.fails.begin(), mistake.fails.end(), [&](const std::string& name) {
        auto result = std::find_if(results.begin(), results.end(),
                                   [&](const GradeResult& entry) { return entry.caseName == name; });
        return result != results.end() && result->propertyCheck;
    });
    if (checksOnly && !mistake.fails.empty()) hintNamesIt = true;
    if (problems.empty() && !hintNamesIt) {
        std::string notes;
        for (std::size_t i = 0; i < hintNotes.size(); ++i) notes += (i ? "; " : "") + hintNotes[i];
        problems.push_back("no failed case's hint names this mistake (" + notes +
                           "); regenerate the gallery with stoa-grade --update-references");
    }

    MistakeVerdict verdict;
    verdict.caught = problems.empty();
    if (verdict.caught) {
        verdict.detail = "caught, hint ok";
    } else {
        verdict.detail = "NOT caught: ";
        for (std::size_t i = 0; i < problems.size(); ++i) verdict.detail += (i ? "; " : "") + problems[i];
    }
    if (!alsoFails.empty()) verdict.detail += " (also fails " + joined(alsoFails) + ")";
    return verdict;
}

namespace {

// Where a run of --check-mistakes (or --check-hints) finds its mistakes and programs.
struct MistakeSource {
    bool outOfGallery = false;
    std::filesystem::path mistakesRoot;   // solutions/, or --check-hints DIR
    std::string programFolder;            // "mistakes" or "out-of-gallery", under the bin folder
};

struct MistakePlan {
    std::vector<MistakeRun> runs;
    std::vector<CaseOutcome> outcomes;    // every run's cases; a run's are [firstJob, firstJob + jobCount)
    std::vector<bool> toGrade;            // per outcome: graded, or known to pass (see casesToGrade())
    std::vector<std::string> notBuilt;    // notes for the mistakes whose program is not built
};

// The cases a gallery mistake must be graded on: those its fails: line names and
// those its gallery entry (written by --update-references, which grades every case)
// records it failing. Every other case passed when the gallery was written, and is
// taken as passed without rendering it: the verdict and the hints are those of a
// run of every case, because a hint depends on the other cases only through which
// of them fail. Empty when every case is to be graded (--every-case).
std::vector<std::string> casesToGrade(const MistakeFile& mistake, const std::vector<CaseJob>& jobs,
                                      bool outOfGallery) {
    std::vector<std::string> names = mistake.fails;
    if (jobs.empty() || outOfGallery) return names;   // a mistake outside the gallery has no entry there
    try {
        for (const KnownMistake& known : loadGallery(jobs.front().reference.parent_path()))
            if (known.name == mistake.name) names.insert(names.end(), known.fails.begin(), known.fails.end());
    } catch (const std::exception&) {
        return {};   // a gallery that does not read: grade every case
    }
    return names;
}

// A case of a mistake's lab left out by casesToGrade(): passed, as the gallery records.
GradeResult assumedPassed(const CaseJob& job) {
    GradeResult result;
    result.lab = job.lab;
    result.caseName = job.spec.name;
    result.status = GradeStatus::Passed;
    result.reason = "not rendered: passed when the gallery was written (--every-case renders it)";
    result.maxPoints = result.points = job.spec.points;
    result.visibility = job.spec.visibility;
    result.propertyCheck = !job.spec.check.empty();
    return result;
}

// The "fails: names a case the manifest does not have" problems of a mistake.
std::string manifestProblemOf(const MistakeFile& mistake, const PlannedLab& lab) {
    std::string problem;
    for (const std::string& name : mistake.fails)
        if (!lab.manifest.find(name))
            problem += (problem.empty() ? "" : "; ") + std::string("fails: names '") + name +
                       "', which is not a case of " + lab.lab + " (cases: " + lab.manifest.caseNames() + ")";
    return problem;
}

MistakePlan planMistakes(const std::vector<PlannedLab>& labs, const MistakeSource& source, const Environment& env,
                         const std::filesystem::path& workDir, bool everyCase) {
    MistakePlan plan;
    for (const PlannedLab& lab : labs) {
        for (MistakeFile& mistake : loadMistakes(source.mistakesRoot / lab.lab)) {
            std::filesystem::path program = mistakeProgram(env.binDir, lab.lab, mistake.name, source.programFolder);
            if (!isExecutable(program)) {
                plan.notBuilt.push_back("note: mistake " + lab.lab + "." + mistake.name + " is not built (no program " +
                                        program.string() + "); skipping it");
                continue;
            }
            MistakeRun run;
            run.manifestProblem = manifestProblemOf(mistake, lab);
            std::vector<CaseJob> jobs =
                caseJobs(lab, program, env.sourceDir, workDir / source.programFolder / (lab.lab + "." + mistake.name));
            // The gallery has no pictures of hidden cases, so they carry no hint: --check-hints skips them.
            if (source.outOfGallery)
                jobs.erase(std::remove_if(jobs.begin(), jobs.end(),
                                          [](const CaseJob& job) { return job.spec.visibility == Visibility::Hidden; }),
                           jobs.end());
            const std::vector<std::string> graded =
                everyCase ? std::vector<std::string>{} : casesToGrade(mistake, jobs, source.outOfGallery);
            run.firstJob = plan.outcomes.size();
            run.jobCount = jobs.size();
            for (CaseOutcome& outcome : plannedOutcomes(std::move(jobs), "mistake " + mistake.name)) {
                plan.toGrade.push_back(graded.empty() ||
                                       std::find(graded.begin(), graded.end(), outcome.job.spec.name) != graded.end());
                if (!plan.toGrade.back()) outcome.result = assumedPassed(outcome.job);
                plan.outcomes.push_back(std::move(outcome));
            }
            run.mistake = std::move(mistake);
            plan.runs.push_back(std::move(run));
        }
    }
    return plan;
}

void explainNothingToCheck(const MistakePlan& plan, const MistakeSource& source, const Environment& env) {
    env.err << "stoa-grade: no mistake program to check in " << (env.binDir / source.programFolder).string();
    if (plan.notBuilt.empty())
        env.err << ": no " << (source.outOfGallery ? source.mistakesRoot.string() + "/" : std::string("solutions/"))
                << "NN_name/mistakes/*.mistake file for the selected labs\n";
    else
        env.err << ": none of the " << plan.notBuilt.size() << " planted mistakes is built; they are built "
                << "by a solutions build with tests (-DSTOA_USE_SOLUTIONS=ON -DSTOA_BUILD_TESTS=ON)\n";
}

// The verdict table; returns how many mistakes were caught.
int printVerdicts(const MistakePlan& plan, const std::vector<CaseOutcome>& outcomes, const MistakeSource& source,
                  std::ostream& out) {
    std::size_t nameWidth = 7, failsWidth = 10;
    for (const MistakeRun& run : plan.runs) {
        nameWidth = std::max(nameWidth, run.mistake.lab.size() + 1 + run.mistake.name.size());
        failsWidth = std::max(failsWidth, joined(run.mistake.fails).size());
    }
    out << "\n" << padded("mistake", nameWidth) << "  " << padded("must fail", failsWidth) << "  result\n";
    out << std::string(nameWidth + failsWidth + 4 + 30, '-') << "\n";
    int caught = 0;
    for (const MistakeRun& run : plan.runs) {
        std::vector<GradeResult> own;
        for (std::size_t i = run.firstJob; i < run.firstJob + run.jobCount; ++i) own.push_back(outcomes[i].result);
        MistakeVerdict verdict =
            source.outOfGallery ? judgeOutOfGallery(run.mistake, own) : judgeMistake(run.mistake, own);
        if (!run.manifestProblem.empty()) verdict = MistakeVerdict{false, "NOT checked: " + run.manifestProblem};
        if (verdict.caught) ++caught;
        out << padded(run.mistake.lab + "." + run.mistake.name, nameWidth) << "  "
            << padded(joined(run.mistake.fails), failsWidth) << "  " << verdict.detail << "\n";
    }
    if (source.outOfGallery)
        out << "\n" << caught << " of " << plan.runs.size()
            << " mistakes outside the gallery fail as their fails: line says and get no wrong hint\n";
    else
        out << "\n" << caught << " of " << plan.runs.size() << " mistakes caught\n";
    return caught;
}

} // namespace

int runCheckMistakes(const Options& options, const Environment& env) {
    std::vector<PlannedLab> labs = planLabs(options, env, false);
    std::filesystem::path solutionsDir = env.sourceDir / "solutions";
    MistakeSource source;
    source.outOfGallery = !options.outOfGalleryDir.empty();
    source.mistakesRoot = source.outOfGallery ? options.outOfGalleryDir : solutionsDir;
    source.programFolder = source.outOfGallery ? "out-of-gallery" : "mistakes";
    if (source.outOfGallery && !std::filesystem::is_directory(source.mistakesRoot)) {
        env.err << "stoa-grade: --check-hints " << source.mistakesRoot.string() << " is not a folder\n";
        return 1;
    }
    if (!std::filesystem::is_directory(solutionsDir)) {
        env.err << "stoa-grade: this tree has no solutions/ folder (a student release), so it has no planted "
                   "mistakes to check\n";
        return 1;
    }

    GradingRun run(options, env);
    MistakePlan plan = planMistakes(labs, source, env, run.workDir(), options.everyCase);
    if (plan.runs.empty()) {
        run.finish(false);
        explainNothingToCheck(plan, source, env);
        return 1;
    }
    for (const std::string& note : plan.notBuilt) env.err << note << "\n";

    // Grade the cases to grade; the others keep their assumed results, in their places.
    std::vector<CaseOutcome> toGrade, outcomes = plan.outcomes;
    for (std::size_t i = 0; i < outcomes.size(); ++i)
        if (plan.toGrade[i]) toGrade.push_back(outcomes[i]);
    std::vector<CaseOutcome> graded = run.grade(std::move(toGrade));
    for (std::size_t i = 0, k = 0; i < outcomes.size(); ++i)
        if (plan.toGrade[i]) outcomes[i] = std::move(graded[k++]);
    run.addHints(outcomes);
    const int caught = printVerdicts(plan, outcomes, source, env.out);
    const bool allCaught = caught == static_cast<int>(plan.runs.size());
    run.finish(!allCaught || !options.workDir.empty());
    return allCaught ? 0 : 1;
}

} // namespace stoa::grader
