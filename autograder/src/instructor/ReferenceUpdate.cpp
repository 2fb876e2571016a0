#include "ReferenceUpdate.hpp"

#include "Grader.hpp"
#include "MistakeGallery.hpp"
#include "RenderTimes.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <cstring>
#include <map>
#include <mutex>
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

int runUpdateReferences(const Options& options, const Environment& env) {
    std::vector<PlannedLab> labs = planLabs(options, env, true);
    if (labs.empty()) {
        env.err << "stoa-grade: no lab program to run in " << env.binDir.string()
                << ": build the solutions first (cmake -DSTOA_USE_SOLUTIONS=ON, then cmake --build)\n";
        return 1;
    }

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
    if (!refusals.empty()) {
        env.err << "stoa-grade: refusing to write references: they must come from the solutions.\n";
        for (const std::string& line : refusals) env.err << "  " << line << "\n";
        env.err << "Configure a solutions build (cmake -S . -B build-solutions -DSTOA_USE_SOLUTIONS=ON), build it, "
                   "and run its stoa-grade --update-references.\n";
        return 1;
    }

    std::filesystem::path workDir = makeWorkDir(options.workDir);
    RunSettings settings = runSettings(options, env.sourceDir, workDir);
    std::vector<CaseJob> jobs;
    for (const PlannedLab& lab : labs) {
        std::vector<CaseJob> labJobs = caseJobs(lab, lab.program, env.sourceDir, workDir);
        jobs.insert(jobs.end(), labJobs.begin(), labJobs.end());
    }
    // The planted mistakes' renders for the gallery go in the same parallel pass.
    std::vector<std::string> notes;
    std::vector<GalleryJob> gallery = galleryJobs(labs, env, workDir, notes);
    for (const std::string& note : notes) env.err << note << "\n";
    std::vector<CaseJob> allJobs = jobs;
    for (const GalleryJob& job : gallery) allJobs.push_back(job.job);

    std::vector<RenderOutcome> renders(allJobs.size());
    std::mutex progressMutex;
    std::size_t done = 0;
    forEachInParallel(allJobs.size(), options.jobs, [&](std::size_t i) {
        renders[i] = renderCase(allJobs[i], settings);
        std::lock_guard<std::mutex> lock(progressMutex);
        env.err << "[" << ++done << "/" << allJobs.size() << "] "
                << (i < jobs.size() ? "" : "mistake " + gallery[i - jobs.size()].mistake.name + ": ")
                << allJobs[i].lab << "/" << allJobs[i].spec.name << " ... "
                << (renders[i].rendered ? "rendered" : statusName(renders[i].status)) << std::endl;
    });

    int failures = 0;
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        bool ok = false;
        std::string line;
        if (!jobs[i].spec.check.empty()) {
            // A property check has no reference image: the solution's must hold.
            ok = renders[i].status == GradeStatus::Passed;
            line = ok ? "property check holds (no reference image)"
                      : std::string(statusName(renders[i].status)) + ": " + renders[i].reason;
        } else {
            line = writeOrKeepImage(jobs[i].reference, jobs[i].spec.compare, renders[i], ok);
        }
        if (!ok) ++failures;
        env.out << jobs[i].lab << "/" << jobs[i].spec.name << ": " << line << "\n";
    }
    env.out << "references in " << (env.sourceDir / "autograder" / "references").string() << ": "
            << jobs.size() - failures << " of " << jobs.size() << " up to date\n";

    // The render times beside the references, from which each case's timeout comes.
    std::map<std::filesystem::path, std::map<std::string, double>> times;
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (renders[i].rendered)
            times[jobs[i].reference.parent_path()][jobs[i].spec.name] = renders[i].process.seconds;
    for (const auto& [folder, measured] : times) {
        std::filesystem::path file = renderTimesPath(folder);
        if (updateRenderTimes(file, measured)) env.out << "render times: updated " << file.string() << "\n";
    }

    if (!gallery.empty() || !notes.empty()) {
        std::vector<RenderOutcome> galleryRenders(renders.begin() + jobs.size(), renders.end());
        GallerySummary summary =
            updateGallery(gallery, galleryRenders, labs, env, options.cases.empty(), env.out);
        env.out << "gallery: " << summary.images << " images (" << summary.written << " new or changed, "
                << summary.removed << " removed";
        if (summary.problems > 0) env.out << ", " << summary.problems << " problems";
        env.out << ") in autograder/references/<lab>/mistakes/\n";
        failures += summary.problems;
    }

    if (failures > 0) {
        env.out << "rendered images: " << workDir.string() << "\n";
        return 1;
    }
    if (options.workDir.empty()) {
        std::error_code ignored;
        std::filesystem::remove_all(workDir, ignored);
    }
    return 0;
}

} // namespace stoa::grader
