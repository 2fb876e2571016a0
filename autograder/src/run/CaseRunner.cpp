#include "CaseRunner.hpp"

#include "Difference.hpp"
#include "LabSandbox.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/image/ImageCompare.hpp>
#include <stoa/lab/LabProtocol.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>

namespace stoa::grader {

namespace {


const char* const kNoReference = "no reference image: run stoa-grade --update-references from a solutions build";

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// Why a process that did not exit 0 or 3 failed, with its last line of output
// when that line says more.
std::string errorReason(const ProcessOutcome& process) {
    if (process.ending == ProcessEnding::TimedOut && process.cpuSeconds >= 0.0) {
        char used[32], limit[32];
        std::snprintf(used, sizeof used, "%.1f", process.cpuSeconds);
        std::snprintf(limit, sizeof limit, "%g", process.timeoutSeconds);
        if (process.busyWhenStopped())
            return std::string("too slow: still computing when its limit of ") + limit +
                   " s ran out (" + used + " s of processor time: it was not waiting on anything)";
        return process.describe() + " without computing (" + used +
               " s of processor time): it waits for something that does not come (a hang)";
    }
    std::string reason = process.describe();
    if (process.exitedWith(kExitUsage)) reason += " (bad usage)";
    if (process.ending == ProcessEnding::Exited || process.ending == ProcessEnding::Signalled) {
        std::string last = process.lastOutputLine();
        if (!last.empty()) reason += ": " + last;
    }
    return reason;
}

// Whatever else it did, a program that leaves processes behind fails: one of
// them could rewrite the reports after the grader has written them.
std::string strayReason(const ProcessOutcome& process) {
    std::size_t count = process.strayProcesses;
    std::string reason = "the lab program left " + std::to_string(count) +
                         (count == 1 ? " process" : " processes") + " running after it " +
                         (process.ending == ProcessEnding::Exited ? "exited" : "ended") +
                         " (killed); a lab program may not leave processes behind";
    if (!process.exitedWith(0)) reason += " (it " + process.describe() + ")";
    return reason;
}

// "references/01_transforms/orbit_front.png, ..." (the last three path components).
std::string changedList(const std::vector<std::filesystem::path>& files) {
    std::string list;
    for (const std::filesystem::path& file : files) {
        std::filesystem::path shown = file.parent_path().parent_path().filename() / file.parent_path().filename() /
                                      file.filename();
        list += (list.empty() ? "" : ", ") + shown.string();
    }
    return list;
}

} // namespace

std::string notAttemptedReason(const ProcessOutcome& process) {
    if (const std::optional<std::string> what = parseNotImplementedLine(process.lastOutputLine()))
        return notImplementedText(*what);
    return "not attempted (a stub is not implemented yet)";
}

RenderOutcome renderCase(const CaseJob& job, const RunSettings& settings) {
    RenderOutcome outcome;
    try {
        std::error_code ignored;
        std::filesystem::remove_all(job.workDir, ignored);
        std::filesystem::create_directories(job.workDir);
        outcome.imagePath = job.workDir / "rendered.png";

        std::vector<std::string> argv{job.program.string(), "--render", job.spec.name, "--output",
                                      outcome.imagePath.string()};
        if (!settings.backend.empty()) {
            argv.push_back("--backend");
            argv.push_back(settings.backend);
        }
        if (!job.casesFile.empty()) {
            argv.push_back("--cases");
            argv.push_back(job.casesFile.string());
        }
        ProcessLimits limits = settings.limits;
        limits.files = labProgramAccess(job, settings);
        limits.environment.push_back("TMPDIR=" + job.workDir.string());
        limits.environment.insert(limits.environment.end(), job.environment.begin(), job.environment.end());
        if (!settings.shaderCache.empty())
            limits.environment.push_back("MESA_SHADER_CACHE_DIR=" + settings.shaderCache.string());
        outcome.process = runProcess(argv, job.workDir, limits);
        if (outcome.process.strayProcesses > 0) {
            outcome.reason = strayReason(outcome.process);
            return outcome;
        }

        if (outcome.process.exitedWith(kExitNotAttempted)) {
            outcome.status = GradeStatus::NotAttempted;
            outcome.reason = notAttemptedReason(outcome.process);
            return outcome;
        }
        if (!job.spec.check.empty()) {
            // A property check draws no picture: its exit status is the verdict and
            // its last line says what it measured.
            if (outcome.process.exitedWith(kExitOk) || outcome.process.exitedWith(kExitCheckFailed)) {
                const bool holds = outcome.process.exitedWith(kExitOk);
                outcome.status = holds ? GradeStatus::Passed : GradeStatus::Failed;
                // The reason the report shows: "holds: ..." / "does not hold: ..." from the verdict line.
                const std::optional<CheckVerdictLine> verdict = parseCheckVerdictLine(outcome.process.lastOutputLine());
                const std::string said = holds ? "holds" : "does not hold";
                outcome.reason = verdict && verdict->name == job.spec.name ? said + ": " + verdict->message : said;
            } else {
                outcome.reason = errorReason(outcome.process);
            }
            return outcome;
        }
        if (!outcome.process.exitedWith(0)) {
            outcome.reason = errorReason(outcome.process);
            return outcome;
        }
        if (!std::filesystem::exists(outcome.imagePath)) {
            outcome.reason = "exited 0 but wrote no image to " + outcome.imagePath.string();
            return outcome;
        }
        try {
            outcome.image = Image::load(outcome.imagePath);
        } catch (const InputError& error) {
            outcome.reason = "the image it wrote does not decode: " + error.message();
            return outcome;
        }
        if (outcome.image.width() != job.spec.width || outcome.image.height() != job.spec.height) {
            outcome.reason = "rendered " + sizeText(outcome.image.width(), outcome.image.height()) + ", expected " +
                             sizeText(job.spec.width, job.spec.height);
            return outcome;
        }
        outcome.rendered = true;
    } catch (const std::exception& error) {
        outcome.rendered = false;
        outcome.status = GradeStatus::Error;
        outcome.reason = std::string("the grader could not run the case: ") + error.what();
    }
    return outcome;
}

GradeResult ungradedResult(const CaseJob& job) {
    GradeResult result;
    result.lab = job.lab;
    result.caseName = job.spec.name;
    result.cascade = job.cascade;
    result.maxPoints = job.spec.points;
    result.visibility = job.spec.visibility;
    result.propertyCheck = !job.spec.check.empty();
    if (!result.propertyCheck) result.referenceImage = job.reference;
    result.maxBadFraction = job.spec.compare.maxBadFraction;
    result.maxFlipMean = job.spec.compare.maxFlipMean;
    return result;
}

namespace {

// The reference picture: the guard's copy, taken before any lab program ran, or
// the file. Empty when there is none; `decodeError` says why one did not decode.
Image referenceOf(const CaseJob& job, ReferenceGuard* guard, std::string& decodeError) {
    Image reference;
    if (guard) {
        if (const Image* guarded = guard->image(job.reference)) reference = *guarded;
        decodeError = guard->decodeError(job.reference);
    } else if (std::filesystem::exists(job.reference)) {
        try {
            reference = Image::load(job.reference);
        } catch (const InputError& error) {
            decodeError = error.message();
        }
    }
    return reference;
}

// Why `reference` cannot be compared with the case's picture (Error or
// NoReference in `status`); nothing when it can.
std::optional<std::string> referenceProblem(const CaseJob& job, const Image& reference, const std::string& decodeError,
                                            GradeStatus& status) {
    status = GradeStatus::Error;
    if (!decodeError.empty())
        return "the reference image does not decode (" + decodeError +
               "); regenerate it with stoa-grade --update-references";
    if (reference.empty()) {
        status = GradeStatus::NoReference;
        return std::string(kNoReference);
    }
    if (reference.width() != job.spec.width || reference.height() != job.spec.height)
        return "the reference is " + sizeText(reference.width(), reference.height()) + " but the case renders " +
               sizeText(job.spec.width, job.spec.height) + "; regenerate it with stoa-grade --update-references";
    return std::nullopt;
}

// The comparison of a rendered picture with its reference, and for a failed
// case where it differs and its heat map (<workDir>/heatmap.png).
void compareWithReference(const CaseJob& job, const Image& rendered, const Image& reference, GradeResult& result) {
    CompareResult comparison = compareImages(rendered, reference, job.spec.compare);
    result.reason = comparison.summary;
    result.metrics = metricsOf(comparison);
    if (comparison.passed) {
        result.status = GradeStatus::Passed;
        result.points = job.spec.points;
        return;
    }
    result.status = GradeStatus::Failed;
    result.difference = describeDifference(rendered, reference, job.spec.compare);
    try {
        std::filesystem::path heatMap = job.workDir / "heatmap.png";
        // From the comparison already made: FLIP does not run twice.
        differenceHeatMap(rendered, reference, comparison, job.spec.compare).savePng(heatMap);
        result.heatMapImage = heatMap;
    } catch (const std::exception& error) {
        result.reason += " (no heat map: " + std::string(error.what()) + ")";
    }
}

} // namespace

GradeResult gradeCase(const CaseJob& job, const RunSettings& settings, ReferenceGuard* guard) {
    GradeResult result = ungradedResult(job);

    RenderOutcome render;
    std::vector<std::filesystem::path> changed;
    if (guard) changed = guard->runAndVerify([&] { render = renderCase(job, settings); });
    else render = renderCase(job, settings);
    result.seconds = render.process.seconds;
    result.timedOut = render.process.ending == ProcessEnding::TimedOut;
    result.busyWhenStopped = render.process.busyWhenStopped();
    result.programOutput = render.process.output;
    if (!render.imagePath.empty() && std::filesystem::exists(render.imagePath)) result.renderedImage = render.imagePath;
    if (!changed.empty()) {
        result.status = GradeStatus::Error;
        result.reason = "tried to modify the reference images (" + changedList(changed) +
                        "); they were restored and the case fails";
        return result;
    }
    if (!render.rendered) {
        result.status = render.status;
        result.reason = render.reason;
        if (result.status == GradeStatus::Passed) result.points = job.spec.points;   // a property check that holds
        return result;
    }

    try {
        std::string decodeError;
        const Image reference = referenceOf(job, guard, decodeError);
        if (std::optional<std::string> problem = referenceProblem(job, reference, decodeError, result.status)) {
            result.reason = *problem;
            return result;
        }
        compareWithReference(job, render.image, reference, result);
    } catch (const std::exception& error) {
        result.status = GradeStatus::Error;
        result.points = 0.0;
        result.reason = std::string("the grader could not compare the images: ") + error.what();
    }
    return result;
}

} // namespace stoa::grader
