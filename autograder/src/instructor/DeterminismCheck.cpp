#include "DeterminismCheck.hpp"

#include "Grader.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

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

std::vector<DeterminismVariant> determinismVariants() {
    return {{"run 1", {}}, {"run 2", {}}, {"LP_NUM_THREADS=1", {"LP_NUM_THREADS=1"}},
            {"LP_NUM_THREADS=2", {"LP_NUM_THREADS=2"}}};
}

namespace {

struct CaseCheck {
    std::string name;                       // "01_transforms/orbit_front"
    std::vector<RenderOutcome> renders;     // one per variant
};

} // namespace

int runDeterminismCheck(const Options& options, const Environment& env) {
    std::vector<PlannedLab> labs = planLabs(options, env, true);
    if (labs.empty()) {
        env.err << "stoa-grade: no lab program to run in " << env.binDir.string()
                << ": build the labs first (cmake --build build) or point --bin-dir at them\n";
        return 1;
    }
    std::filesystem::path workDir = makeWorkDir(options.workDir);
    std::vector<DeterminismVariant> variants = determinismVariants();

    // Every (case, variant) pair is a job; each renders into its own folder.
    std::vector<CaseJob> cases;
    for (const PlannedLab& lab : labs) {
        std::vector<CaseJob> labJobs = caseJobs(lab, lab.program, env.sourceDir, workDir);
        cases.insert(cases.end(), labJobs.begin(), labJobs.end());
    }
    std::vector<CaseCheck> checks(cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        checks[i].name = cases[i].lab + "/" + cases[i].spec.name;
        checks[i].renders.resize(variants.size());
    }
    RunSettings base = runSettings(options, env.sourceDir, workDir);
    std::size_t total = cases.size() * variants.size();
    forEachInParallel(total, options.jobs, [&](std::size_t index) {
        std::size_t caseIndex = index / variants.size();
        std::size_t variantIndex = index % variants.size();
        CaseJob job = cases[caseIndex];
        job.workDir = job.workDir / ("variant-" + std::to_string(variantIndex));
        RunSettings settings = base;
        for (const std::string& assignment : variants[variantIndex].environment)
            settings.limits.environment.push_back(assignment);
        checks[caseIndex].renders[variantIndex] = renderCase(job, settings);
    });

    int differing = 0, failed = 0, skipped = 0, identical = 0;
    for (std::size_t caseIndex = 0; caseIndex < checks.size(); ++caseIndex) {
        const CaseCheck& check = checks[caseIndex];
        const RenderOutcome& first = check.renders[0];
        if (!cases[caseIndex].spec.check.empty()) {
            // A property check draws nothing: its verdict must be the same in every run.
            const bool same = std::all_of(check.renders.begin(), check.renders.end(), [&](const RenderOutcome& run) {
                return run.status == first.status && run.reason == first.reason;
            });
            if (first.status == GradeStatus::NotAttempted) {
                ++skipped;
                env.out << check.name << ": skipped, not attempted (" << first.reason << ")\n";
            } else if (first.status != GradeStatus::Passed && first.status != GradeStatus::Failed) {
                ++failed;
                env.out << check.name << ": FAILED to run the check: " << first.reason << "\n";
            } else if (same) {
                ++identical;
                env.out << check.name << ": the same verdict in " << variants.size() << " runs (a property check)\n";
            } else {
                ++differing;
                env.out << check.name << ": DIFFERS: the property check's verdict changes between runs\n";
            }
            continue;
        }
        auto notRendered = std::find_if(check.renders.begin(), check.renders.end(),
                                        [](const RenderOutcome& render) { return !render.rendered; });
        if (notRendered != check.renders.end()) {
            std::size_t variant = static_cast<std::size_t>(notRendered - check.renders.begin());
            if (notRendered->status == GradeStatus::NotAttempted) {
                ++skipped;
                env.out << check.name << ": skipped, not attempted (" << notRendered->reason << ")\n";
            } else {
                ++failed;
                env.out << check.name << ": FAILED to render (" << variants[variant].name
                        << "): " << notRendered->reason << "\n";
            }
            continue;
        }
        std::vector<std::string> differences;
        for (std::size_t v = 1; v < check.renders.size(); ++v) {
            ImageDifference difference = compareExactly(first.image, check.renders[v].image);
            if (!difference.identical())
                differences.push_back(variants[v].name + " vs " + variants[0].name + ": " + difference.describe());
        }
        if (differences.empty()) {
            ++identical;
            env.out << check.name << ": identical in " << variants.size() << " renders\n";
        } else {
            ++differing;
            env.out << check.name << ": DIFFERS";
            for (const std::string& line : differences) env.out << "\n    " << line;
            env.out << "\n";
        }
    }

    env.out << "\ndeterminism: " << identical << " identical, " << differing << " differing, " << failed
            << " failed to render, " << skipped << " not attempted (renders: ";
    for (std::size_t v = 0; v < variants.size(); ++v) env.out << (v ? ", " : "") << variants[v].name;
    env.out << ")\n";
    if (differing + failed > 0) {
        env.out << "rendered images: " << workDir.string() << "/<lab>/<case>/variant-N/\n";
        return 1;
    }
    if (options.workDir.empty()) {
        std::error_code ignored;
        std::filesystem::remove_all(workDir, ignored);
    }
    if (identical == 0) {
        env.err << "stoa-grade: no case rendered, so nothing was compared (run it on a build whose labs are done)\n";
        return 1;
    }
    return 0;
}

} // namespace stoa::grader
