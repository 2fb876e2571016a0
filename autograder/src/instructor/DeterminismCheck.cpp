#include "DeterminismCheck.hpp"

#include "Grader.hpp"
#include "GradingRun.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <sstream>

#include <unistd.h>

namespace stoa::grader {

std::string ImageDifference::describe() const {
    if (!sameSize) return "sizes differ";
    if (differingPixels == 0) return "identical";
    std::ostringstream text;
    text << differingPixels << (differingPixels == 1 ? " pixel differs" : " pixels differ") << ", by at most "
         << maxChannelDifference << (maxChannelDifference == 1 ? " level" : " levels");
    return text.str();
}

ImageDifference compareExactly(const Image& a, const Image& b) {
    ImageDifference difference;
    if (a.width() != b.width() || a.height() != b.height()) {
        difference.sameSize = false;
        return difference;
    }
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            glm::u8vec4 p = a.pixel(x, y);
            glm::u8vec4 q = b.pixel(x, y);
            int largest = 0;
            for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(p[c]) - int(q[c])));
            if (largest > 0) {
                ++difference.differingPixels;
                difference.maxChannelDifference = std::max(difference.maxChannelDifference, largest);
            }
        }
    return difference;
}

std::vector<DeterminismVariant> determinismVariants(int defaultThreads) {
    std::vector<DeterminismVariant> variants = {{"run 1", {}}, {"run 2", {}}, {"LP_NUM_THREADS=1", {"LP_NUM_THREADS=1"}}};
    if (defaultThreads != 2) variants.push_back({"LP_NUM_THREADS=2", {"LP_NUM_THREADS=2"}});
    return variants;
}

int llvmpipeDefaultThreads() {
    if (const char* value = std::getenv("LP_NUM_THREADS"); value && *value) return std::atoi(value);
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    return online > 1 ? static_cast<int>(online) : 0;   // llvmpipe renders on the calling thread on one CPU
}

namespace {

enum class Verdict { Identical, Differs, Failed, Skipped };

struct CaseVerdict {
    Verdict verdict;
    std::string line;   // what the report says after the case's name
};

// A property check draws nothing: its verdict must be the same in every run.
CaseVerdict judgeCheck(const std::vector<CaseOutcome>& renders) {
    const RenderOutcome& first = renders[0].render;
    const bool same = std::all_of(renders.begin(), renders.end(), [&](const CaseOutcome& run) {
        return run.render.status == first.status && run.render.reason == first.reason;
    });
    if (first.status == GradeStatus::NotAttempted) return {Verdict::Skipped, "skipped, not attempted (" + first.reason + ")"};
    if (first.status != GradeStatus::Passed && first.status != GradeStatus::Failed)
        return {Verdict::Failed, "FAILED to run the check: " + first.reason};
    if (same)
        return {Verdict::Identical, "the same verdict in " + std::to_string(renders.size()) + " runs (a property check)"};
    return {Verdict::Differs, "DIFFERS: the property check's verdict changes between runs"};
}

// The renders of one case, each against the first, bit for bit.
CaseVerdict judgeRenders(const std::vector<CaseOutcome>& renders) {
    for (const CaseOutcome& run : renders) {
        if (run.render.rendered) continue;
        if (run.render.status == GradeStatus::NotAttempted)
            return {Verdict::Skipped, "skipped, not attempted (" + run.render.reason + ")"};
        return {Verdict::Failed, "FAILED to render (" + run.label + "): " + run.render.reason};
    }
    std::string differences;
    for (std::size_t v = 1; v < renders.size(); ++v) {
        ImageDifference difference = compareExactly(renders[0].render.image, renders[v].render.image);
        if (!difference.identical())
            differences += "\n    " + renders[v].label + " vs " + renders[0].label + ": " + difference.describe();
    }
    if (differences.empty()) return {Verdict::Identical, "identical in " + std::to_string(renders.size()) + " renders"};
    return {Verdict::Differs, "DIFFERS" + differences};
}

// Every (case, variant) pair, each rendering into its own folder; a case's
// variants are consecutive, in the order of `variants`.
std::vector<CaseOutcome> planVariants(const std::vector<PlannedLab>& labs, const Environment& env,
                                      const std::filesystem::path& workDir,
                                      const std::vector<DeterminismVariant>& variants) {
    std::vector<CaseOutcome> planned;
    for (const PlannedLab& lab : labs)
        for (const CaseJob& job : caseJobs(lab, lab.program, env.sourceDir, workDir))
            for (std::size_t v = 0; v < variants.size(); ++v) {
                CaseJob variant = job;
                variant.workDir = job.workDir / ("variant-" + std::to_string(v));
                variant.environment = variants[v].environment;
                for (CaseOutcome& outcome : plannedOutcomes({variant}, variants[v].name))
                    planned.push_back(std::move(outcome));
            }
    return planned;
}

} // namespace

int runDeterminismCheck(const Options& options, const Environment& env) {
    std::vector<PlannedLab> labs = planLabs(options, env, true);
    if (noProgramToRun(labs, env, "build the labs first (cmake --build build) or point --bin-dir at them")) return 1;
    GradingRun run(options, env);
    const int defaultThreads = llvmpipeDefaultThreads();
    const std::vector<DeterminismVariant> variants = determinismVariants(defaultThreads);
    const std::vector<CaseOutcome> renders = run.render(planVariants(labs, env, run.workDir(), variants));

    std::map<Verdict, int> counts;
    for (std::size_t first = 0; first < renders.size(); first += variants.size()) {
        const std::vector<CaseOutcome> chunk(renders.begin() + first, renders.begin() + first + variants.size());
        const CaseJob& job = chunk[0].job;
        const CaseVerdict verdict = job.spec.check.empty() ? judgeRenders(chunk) : judgeCheck(chunk);
        ++counts[verdict.verdict];
        env.out << job.lab << "/" << job.spec.name << ": " << verdict.line << "\n";
    }

    env.out << "\ndeterminism: " << counts[Verdict::Identical] << " identical, " << counts[Verdict::Differs]
            << " differing, " << counts[Verdict::Failed] << " failed to render, " << counts[Verdict::Skipped]
            << " not attempted (renders: ";
    for (std::size_t v = 0; v < variants.size(); ++v) env.out << (v ? ", " : "") << variants[v].name;
    if (defaultThreads == 2) env.out << "; runs 1 and 2 are LP_NUM_THREADS=2, llvmpipe's default here";
    env.out << ")\n";
    const bool trouble = counts[Verdict::Differs] + counts[Verdict::Failed] > 0;
    run.finish(trouble, "rendered images", "/<lab>/<case>/variant-N/");
    if (trouble) return 1;
    if (counts[Verdict::Identical] == 0) {
        env.err << "stoa-grade: no case rendered, so nothing was compared (run it on a build whose labs are done)\n";
        return 1;
    }
    return 0;
}

} // namespace stoa::grader
