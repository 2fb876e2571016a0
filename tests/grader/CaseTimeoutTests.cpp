// Case timeouts from the solutions' render times (autograder/src/run/RenderTimes.hpp):
// the policy, the render-times file, and a hanging program paying the full limit
// once and the short one after.

#include "catch.hpp"

#include "Grader.hpp"
#include "HostileJob.hpp"
#include "RenderTimes.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>

#include <chrono>
#include <fstream>
#include <iterator>

using namespace stoa::grader;

namespace {

std::string readAll(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

} // namespace

TEST_CASE("caseTimeouts: a multiple of the solution's render time with a floor", "[grader][timeouts]") {
    CaseTimeouts quick = caseTimeouts(0.4, false);
    CHECK(quick.first == kTimeoutFloorSeconds);
    CHECK(quick.afterTimeout == kShortTimeoutFloorSeconds);

    CaseTimeouts slow = caseTimeouts(2.5, false);
    CHECK(slow.first == Approx(kTimeoutFactor * 2.5));
    CHECK(slow.afterTimeout == Approx(kShortTimeoutFactor * 2.5));
    CHECK(slow.afterTimeout < slow.first);

    CaseTimeouts unknown = caseTimeouts(0.0, false);
    CHECK(unknown.first == kUnrecordedTimeoutSeconds);

    CaseTimeouts sanitized = caseTimeouts(0.4, true);
    CHECK(sanitized.first == Approx(kTimeoutFloorSeconds * kSanitizerSlowdown));
    CHECK(sanitized.afterTimeout == Approx(kShortTimeoutFloorSeconds * kSanitizerSlowdown));
}

TEST_CASE("render times: written rounded up, kept through noise, rewritten when they double", "[grader][timeouts]") {
    stoa::test::TempFolder folder("render-times");
    std::filesystem::path file = renderTimesPath(folder.path());
    CHECK(readRenderTimes(file).empty());   // no file: no times

    CHECK(updateRenderTimes(file, {{"orbit_front", 0.31}, {"wide_lens", 1.0}}));
    std::map<std::string, double> times = readRenderTimes(file);
    CHECK(times.size() == 2);
    CHECK(times["orbit_front"] == Approx(0.4));
    CHECK(times["wide_lens"] == Approx(1.0));

    // Noise within a factor of two leaves the file alone.
    std::string before = readAll(file);
    CHECK_FALSE(updateRenderTimes(file, {{"orbit_front", 0.7}, {"wide_lens", 0.55}}));
    CHECK(readAll(file) == before);

    // More than double: rewritten; the other case's line stays.
    CHECK(updateRenderTimes(file, {{"orbit_front", 0.95}}));
    times = readRenderTimes(file);
    CHECK(times["orbit_front"] == Approx(1.0));
    CHECK(times["wide_lens"] == Approx(1.0));
}

TEST_CASE("render times: a bad line names the file and the line", "[grader][timeouts]") {
    stoa::test::TempFolder folder("render-times-bad");
    std::filesystem::path file = renderTimesPath(folder.path());
    std::ofstream(file) << "# comment\norbit_front 0.4\nwide_lens fast\n";
    try {
        readRenderTimes(file);
        FAIL("no error for 'wide_lens fast'");
    } catch (const stoa::InputError& error) {
        CHECK(error.file() == file.string());
        CHECK(error.line() == 3);
        CHECK_THAT(error.message(), Catch::Matchers::Contains("wide_lens fast"));
    }
}

TEST_CASE("a program that hangs pays its case's limit once, then the short limit three times, then is not run",
          "[grader][timeouts][isolation]") {
    stoa::test::TempFolder folder("hanging");
    std::vector<CaseJob> jobs;
    for (int i = 0; i < 6; ++i) {
        CaseJob job = stoa::test::hostileJob("infinite_loop", folder.path() / "references",
                                             folder.path() / ("work" + std::to_string(i)));
        job.timeouts.first = 1.5;
        job.timeouts.afterTimeout = 0.5;
        jobs.push_back(job);
    }
    RunSettings settings;
    settings.caseTimeouts = true;
    std::vector<GradeResult> results = gradeCases(jobs, settings, 1);
    REQUIRE(results.size() == 6);
    using Catch::Matchers::Contains;
    using Catch::Matchers::Equals;
    using Catch::Matchers::StartsWith;
    // Busy all along: too slow (or endless), never "waiting".
    CHECK_THAT(results[0].reason, StartsWith("too slow: still computing when its limit of 1.5 s ran out ("));
    CHECK(results[0].busyWhenStopped);
    for (int i = 1; i < 4; ++i) {
        CHECK_THAT(results[i].reason, StartsWith("too slow: still computing when its limit of 0.5 s ran out"));
        CHECK_THAT(results[i].reason, Contains("the short limit: the program timed out on an earlier case"));
    }
    static_assert(kMaxTimeoutsInARow == 3, "the cases below expect three short-limit timeouts before the rest is skipped");
    for (int i = 4; i < 6; ++i) {
        CHECK_THAT(results[i].reason, StartsWith("not run: after a first timeout the program ran out of the short "
                                                 "limit on 3 cases in a row, still computing"));
        CHECK_FALSE(results[i].timedOut);
        CHECK(results[i].seconds == 0.0);
        CHECK(results[i].maxPoints == 1);
    }
    for (const GradeResult& result : results) {
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.points == 0);
    }

    // A case that finishes in time breaks the streak: hang, hang, answer, hang, hang all run.
    std::vector<CaseJob> mixed(jobs.begin(), jobs.begin() + 5);
    mixed[2].spec.name = "good";
    for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i].workDir = folder.path() / ("mixed" + std::to_string(i));
    results = gradeCases(mixed, settings, 1);
    CHECK_FALSE(results[2].timedOut);
    CHECK(results[3].timedOut);
    CHECK(results[4].timedOut);
    CHECK_THAT(results[4].reason, Contains("the short limit"));

    // With --timeout (caseTimeouts off), every case gets that one limit.
    settings = RunSettings{};
    settings.limits = defaultLimits(0.5);
    jobs.resize(4);
    results = gradeCases(jobs, settings, 1);
    for (const GradeResult& result : results)
        CHECK_THAT(result.reason, StartsWith("too slow: still computing when its limit of 0.5 s ran out"));
}

TEST_CASE("slow is not a hang: a program too slow on its first cases keeps the cases it finishes in time",
          "[grader][timeouts][isolation]") {
    // Lab 07 with a BVH that never splits: its three ray-cast cases come first
    // and run far past their limit; its other cases finish in time. Only the
    // ray-cast cases may be lost.
    stoa::test::TempFolder folder("slow-first");
    std::vector<CaseJob> jobs;
    for (const char* name : {"infinite_loop", "infinite_loop", "infinite_loop", "good", "good", "good"}) {
        CaseJob job = stoa::test::hostileJob(name, folder.path() / "references",
                                             folder.path() / ("work" + std::to_string(jobs.size())));
        job.timeouts.first = 1.5;
        job.timeouts.afterTimeout = 0.5;
        jobs.push_back(job);
    }
    RunSettings settings;
    settings.caseTimeouts = true;
    const std::vector<GradeResult> results = gradeCases(jobs, settings, 1);
    REQUIRE(results.size() == 6);
    for (int i = 0; i < 3; ++i) {
        CHECK(results[i].timedOut);
        CHECK_THAT(results[i].reason, Catch::Matchers::StartsWith("too slow: still computing"));
    }
    for (int i = 3; i < 6; ++i) {
        INFO(results[i].reason);
        CHECK(results[i].status == GradeStatus::Passed);
    }
}

TEST_CASE("a hanging lab costs at most 30 s to grade with its real limits, busy or waiting", "[grader][timeouts][isolation]") {
    // Eight cases whose solution renders in 0.5 s (a limit of 15 s, 5 s once
    // the program has timed out), graded with two jobs as stoa-grade does:
    // four spin, four sleep. The first two pay the full limit, three more the
    // short one, and the rest are not run. The waiting ones say so.
    stoa::test::TempFolder folder("hang-budget");
    std::vector<CaseJob> jobs;
    for (int i = 0; i < 8; ++i) {
        CaseJob job = stoa::test::hostileJob(i % 2 ? "sleep_forever" : "infinite_loop", folder.path() / "references",
                                             folder.path() / ("work" + std::to_string(i)));
        job.timeouts = caseTimeouts(0.5, false);
        jobs.push_back(job);
    }
    REQUIRE(jobs[0].timeouts.first == kTimeoutFloorSeconds);
    REQUIRE(jobs[0].timeouts.afterTimeout == kShortTimeoutFloorSeconds);
    RunSettings settings;
    settings.caseTimeouts = true;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<GradeResult> results = gradeCases(jobs, settings, 2);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds <= 30.0);
    int notRun = 0;
    for (const GradeResult& result : results) {
        INFO(result.caseName << ": " << result.reason);
        CHECK(result.status == GradeStatus::Error);
        if (result.reason.rfind("not run:", 0) == 0) ++notRun;
        else if (result.caseName == "sleep_forever")
            CHECK_THAT(result.reason, Catch::Matchers::Contains("without computing") &&
                                          Catch::Matchers::Contains("(a hang)"));
        else
            CHECK_THAT(result.reason, Catch::Matchers::StartsWith("too slow: still computing"));
    }
    CHECK(notRun >= 2);
}
