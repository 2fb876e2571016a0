#include "Grader.hpp"

#include <stoa/core/InputError.hpp>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <thread>

namespace stoa::grader {

void forEachInParallel(std::size_t count, int jobs, const std::function<void(std::size_t)>& task) {
    std::atomic<std::size_t> next{0};
    auto worker = [&]() {
        for (std::size_t i = next++; i < count; i = next++) task(i);
    };
    std::size_t threadCount = std::min<std::size_t>(count, static_cast<std::size_t>(std::max(1, jobs)));
    if (threadCount <= 1) {
        worker();
        return;
    }
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < threadCount; ++i) threads.emplace_back(worker);
    for (std::thread& thread : threads) thread.join();
}

GradeResult notRunAfterTimeouts(const CaseJob& job, int timeoutsInARow, bool busy) {
    GradeResult result = ungradedResult(job);
    result.status = GradeStatus::Error;
    result.reason = "not run: after a first timeout the program ran out of the short limit on " +
                    std::to_string(timeoutsInARow) + " cases in a row, " +
                    (busy ? "still computing (too slow, or a loop that never ends); make it finish and grade again"
                          : "without computing, so it hangs; fix what it waits for and grade again");
    return result;
}

std::vector<GradeResult> gradeCases(const std::vector<CaseJob>& jobs, const RunSettings& settings, int parallelJobs,
                                    const ProgressCallback& progress) {
    std::vector<GradeResult> results(jobs.size());
    // Every reference is read (and kept) before the first lab program runs.
    std::vector<std::filesystem::path> references;
    std::vector<std::filesystem::path> workFolders;
    for (const CaseJob& job : jobs) {
        references.push_back(job.reference);
        workFolders.push_back(job.workDir);
    }
    ReferenceGuard guard(references, workFolders);
    std::mutex progressMutex;
    std::size_t done = 0;
    // A program that has timed out once may hang: its remaining cases get the
    // short limit, and once it has run out of the short limit kMaxTimeoutsInARow
    // times in a row, the rest of its cases are not run (RenderTimes.hpp). The
    // timeouts under the case's full limit do not count towards that: a correct
    // but slow program loses the cases that are too slow, and its next case that
    // finishes in time ends the streak.
    struct ProgramTimeouts {
        bool any = false;   // it has timed out at least once
        int inARow = 0;     // short-limit timeouts since its last case that finished in time
        bool busy = false;  // the last of them was still computing
    };
    std::map<std::filesystem::path, ProgramTimeouts> timeouts;
    forEachInParallel(jobs.size(), parallelJobs, [&](std::size_t i) {
        RunSettings caseSettings = settings;
        ProgramTimeouts seen;
        if (settings.caseTimeouts) {
            std::unique_lock<std::mutex> lock(progressMutex);
            seen = timeouts[jobs[i].program];
            lock.unlock();
            caseSettings.limits = withTimeout(settings.limits, seen.any ? jobs[i].timeouts.afterTimeout
                                                                              : jobs[i].timeouts.first);
        }
        if (seen.inARow >= kMaxTimeoutsInARow) {
            results[i] = notRunAfterTimeouts(jobs[i], seen.inARow, seen.busy);
        } else {
            results[i] = gradeCase(jobs[i], caseSettings, &guard);
            if (seen.any && results[i].timedOut)
                results[i].reason += " (the short limit: the program timed out on an earlier case)";
        }
        std::lock_guard<std::mutex> lock(progressMutex);
        if (settings.caseTimeouts && seen.inARow < kMaxTimeoutsInARow) {
            ProgramTimeouts& program = timeouts[jobs[i].program];
            if (results[i].timedOut) {
                if (seen.any) ++program.inARow;   // under the short limit
                program.any = true;
                program.busy = results[i].busyWhenStopped;
            } else {
                program.inARow = 0;
            }
        }
        ++done;
        if (progress) progress(i, results[i], done, jobs.size());
    });
    return results;
}

std::string progressLine(const GradeResult& result, std::size_t done, std::size_t total, const std::string& label) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f", result.seconds);
    return "[" + std::to_string(done) + "/" + std::to_string(total) + "] " + (label.empty() ? "" : label + ": ") +
           result.fullName() + " ... " +
           statusName(result.status) + " (" + seconds + " s)";
}

std::filesystem::path makeWorkDir(const std::filesystem::path& requested) {
    if (!requested.empty()) {
        std::error_code error;
        std::filesystem::create_directories(requested, error);
        if (error || !std::filesystem::is_directory(requested))
            throw InputError(requested.string(), 0, "cannot create the work folder: " + error.message());
        return std::filesystem::absolute(requested);
    }
    std::error_code error;
    std::filesystem::path temp = std::filesystem::temp_directory_path(error);
    if (error) temp = "/tmp";
    std::string pattern = (temp / "stoa-grade-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
        throw InputError(pattern, 0, std::string("cannot create a temporary work folder: ") + std::strerror(errno));
    return pattern;
}

} // namespace stoa::grader
