#pragma once
// Grades many cases, `jobs` of them at once: a small pool of worker threads,
// each running one lab program at a time in its own child process.

#include "CaseRunner.hpp"
#include "GradeResult.hpp"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace stoa::grader {

/// Calls `task(i)` for every i in [0, count), on up to `jobs` threads at once,
/// and returns when all are done. `task` must not throw.
void forEachInParallel(std::size_t count, int jobs, const std::function<void(std::size_t)>& task);

/// Called as each case finishes (from one thread at a time): the job's index in
/// `jobs`, its result, how many are done, and how many there are.
using ProgressCallback =
    std::function<void(std::size_t index, const GradeResult& result, std::size_t done, std::size_t total)>;

/// Grades every job; the results come back in the order of `jobs`. The reference
/// images are guarded (ReferenceGuard) while the lab programs run: a case after
/// which one changed fails, and the file is restored. With several jobs at once,
/// the blame falls on the case that finished first after the change. With
/// `settings.caseTimeouts`, each job runs under its own `timeouts`: the short one
/// once its program has timed out, and none at all (the case fails "not run")
/// once its program has timed out kMaxTimeoutsInARow times in a row.
std::vector<GradeResult> gradeCases(const std::vector<CaseJob>& jobs, const RunSettings& settings, int parallelJobs,
                                    const ProgressCallback& progress = {});

/// The result of a case that was not run because its program hangs.
GradeResult notRunAfterTimeouts(const CaseJob& job, int timeoutsInARow, bool busy);

/// "[3/12] 01_transforms/orbit_front ... passed (0.8 s)"; a `label` goes before
/// the case: "[3/12] mistake no_half_vector: 02_shading/sun ... failed (0.6 s)".
std::string progressLine(const GradeResult& result, std::size_t done, std::size_t total,
                         const std::string& label = "");

/// `requested` (created when missing), or a new folder stoa-grade-XXXXXX in the
/// system's temp folder when `requested` is empty. Returned as an absolute path.
/// Throws InputError when it cannot be created.
std::filesystem::path makeWorkDir(const std::filesystem::path& requested);

} // namespace stoa::grader
