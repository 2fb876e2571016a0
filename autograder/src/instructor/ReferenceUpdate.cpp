#include "ReferenceUpdate.hpp"

#include "Grader.hpp"
#include "GradingRun.hpp"
#include "MistakeGallery.hpp"
#include "RenderTimes.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <cstring>
#include <map>
#include <sstream>

namespace stoa::grader {

namespace {

constexpr double kInfoTimeoutSeconds = 30.0;

bool samePixels(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() && a.channels() == b.channels() &&
           std::memcmp(a.data(), b.data(), a.sizeInBytes()) == 0;
}

} // namespace

std::string writeOrKeepImage(const std::filesystem::path& target, const CompareOptions& compare,
                             const RenderOutcome& render, bool& ok) {
    ok = false;
    if (!render.rendered) return std::string(statusName(render.status)) + ": " + render.reason;
    std::error_code error;
    bool existed = std::filesystem::exists(target, error);
    std::string verdict = "new";
    if (existed) {
        Image previous;
        try {
            previous = Image::load(target);
        } catch (const InputError&) {
            previous = Image();
        }
        if (!previous.empty() && samePixels(previous, render.image)) {
            ok = true;
            return "unchanged";
        }
        if (previous.empty()) {
            verdict = "changed (the old reference did not decode)";
        } else {
            CompareResult comparison = compareImages(render.image, previous, compare);
            if (comparison.passed) {
                ok = true;
                return "unchanged (within tolerance: " + comparison.summary + ")";
            }
            verdict = "changed (" + comparison.summary + ")";
        }
    }
    std::filesystem::create_directories(target.parent_path(), error);
    std::filesystem::copy_file(render.imagePath, target, std::filesystem::copy_options::overwrite_existing, error);
    if (error) return "error: cannot write " + target.string() + ": " + error.message();
    ok = true;
    return verdict;
}

std::string trackFromInfo(const std::string& infoOutput) {
    std::istringstream lines(infoOutput);
    for (std::string line; std::getline(lines, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.rfind("track=", 0) == 0) return line.substr(6);
    }
    return "";
}

namespace {

// References come from the solutions only: each lab program must say it was
// built from them (its --info). Returns the refusals, none when all may write.
std::vector<std::string> refusalsToWrite(const std::vector<PlannedLab>& labs) {
    ProcessLimits infoLimits = withTimeout(defaultLimits(kInfoTimeoutSeconds), kInfoTimeoutSeconds);
    std::vector<std::string> refusals;
    for (const PlannedLab& lab : labs) {
        ProcessOutcome info = runProcess({lab.program.string(), "--info"}, {}, infoLimits);
        std::string track = info.exitedWith(0) ? trackFromInfo(info.output) : "";
        if (!info.exitedWith(0))
            refusals.push_back(lab.program.string() + " --info " + info.describe());
        else if (track != "solutions")
            refusals.push_back(lab.program.string() + " is built from " +
                               (track.empty() ? std::string("an unknown track (no track= line)") : "track=" + track));
    }
    return refusals;
}

// Writes each case's reference (or, for a property check, checks that the
// solution's holds); returns how many could not be written.
int writeReferences(const std::vector<CaseOutcome>& cases, const Environment& env) {
    int failures = 0;
    for (const CaseOutcome& outcome : cases) {
        const CaseJob& job = outcome.job;
        bool ok = false;
        std::string line;
        if (!job.spec.check.empty()) {
            // A property check has no reference image: the solution's must hold.
            ok = outcome.render.status == GradeStatus::Passed;
            line = ok ? "property check holds (no reference image)"
                      : std::string(statusName(outcome.render.status)) + ": " + outcome.render.reason;
        } else {
            line = writeOrKeepImage(job.reference, job.spec.compare, outcome.render, ok);
        }
        if (!ok) ++failures;
        env.out << job.lab << "/" << job.spec.name << ": " << line << "\n";
    }
    env.out << "references in " << (env.sourceDir / "autograder" / "references").string() << ": "
            << cases.size() - failures << " of " << cases.size() << " up to date\n";
    return failures;
}

// The render times beside the references, from which each case's timeout comes.
void writeRenderTimes(const std::vector<CaseOutcome>& cases, const Environment& env) {
    std::map<std::filesystem::path, std::map<std::string, double>> times;
    for (const CaseOutcome& outcome : cases)
        if (outcome.render.rendered)
            times[outcome.job.reference.parent_path()][outcome.job.spec.name] = outcome.render.process.seconds;
    for (const auto& [folder, measured] : times) {
        std::filesystem::path file = renderTimesPath(folder);
        if (updateRenderTimes(file, measured)) env.out << "render times: updated " << file.string() << "\n";
    }
}

} // namespace

int runUpdateReferences(const Options& options, const Environment& env) {
    std::vector<PlannedLab> labs = planLabs(options, env, true);
    if (noProgramToRun(labs, env, "build the solutions first (cmake -DSTOA_USE_SOLUTIONS=ON, then cmake --build)"))
        return 1;
    const std::vector<std::string> refusals = refusalsToWrite(labs);
    if (!refusals.empty()) {
        env.err << "stoa-grade: refusing to write references: they must come from the solutions.\n";
        for (const std::string& line : refusals) env.err << "  " << line << "\n";
        env.err << "Configure a solutions build (cmake -S . -B build-solutions -DSTOA_USE_SOLUTIONS=ON), build it, "
                   "and run its stoa-grade --update-references.\n";
        return 1;
    }

    GradingRun run(options, env);
    std::vector<CaseOutcome> planned;
    for (const PlannedLab& lab : labs)
        for (CaseOutcome& outcome : plannedOutcomes(caseJobs(lab, lab.program, env.sourceDir, run.workDir())))
            planned.push_back(std::move(outcome));
    const std::size_t caseCount = planned.size();
    // The planted mistakes' renders for the gallery go in the same parallel pass.
    std::vector<std::string> notes;
    std::vector<GalleryJob> gallery = galleryJobs(labs, env, run.workDir(), notes);
    for (const std::string& note : notes) env.err << note << "\n";
    for (const GalleryJob& job : gallery)
        for (CaseOutcome& outcome : plannedOutcomes({job.job}, "mistake " + job.mistake.name))
            planned.push_back(std::move(outcome));

    std::vector<CaseOutcome> rendered = run.render(std::move(planned));
    std::vector<CaseOutcome> galleryRendered(rendered.begin() + caseCount, rendered.end());
    rendered.resize(caseCount);
    int failures = writeReferences(rendered, env);
    writeRenderTimes(rendered, env);

    if (!gallery.empty() || !notes.empty()) {
        std::vector<RenderOutcome> galleryRenders;
        for (const CaseOutcome& outcome : galleryRendered) galleryRenders.push_back(outcome.render);
        GallerySummary summary = updateGallery(gallery, galleryRenders, labs, env, options.cases.empty(), env.out);
        env.out << "gallery: " << summary.images << " images (" << summary.written << " new or changed, "
                << summary.removed << " removed";
        if (summary.problems > 0) env.out << ", " << summary.problems << " problems";
        env.out << ") in autograder/references/<lab>/mistakes/\n";
        failures += summary.problems;
    }
    run.finish(failures > 0, "rendered images");
    return failures > 0 ? 1 : 0;
}

} // namespace stoa::grader
