// Case timeouts from the solutions' render times (autograder/src/run/RenderTimes.hpp):
// the policy, the render-times file, and a hanging program paying the full limit
// once and the short one after.

#include "catch.hpp"

#include "Grader.hpp"
#include "HostileJob.hpp"
#include "RenderTimes.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>

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

TEST_CASE("a program that hangs pays its case's limit once, then the short limit, then is not run",
          "[grader][timeouts][isolation]") {
    stoa::test::TempFolder folder("hanging");
    std::vector<CaseJob> jobs;
    for (int i = 0; i < 5; ++i) {
        CaseJob job = stoa::test::hostileJob("infinite_loop", folder.path() / "references",
                                             folder.path() / ("work" + std::to_string(i)));
        job.timeouts.first = 1.5;
        job.timeouts.afterTimeout = 0.5;
        jobs.push_back(job);
    }
    RunSettings settings;
    settings.caseTimeouts = true;
    std::vector<GradeResult> results = gradeCases(jobs, settings, 1);
    REQUIRE(results.size() == 5);
    using Catch::Matchers::Contains;
    using Catch::Matchers::Equals;
    using Catch::Matchers::StartsWith;
    CHECK_THAT(results[0].reason, Equals("timed out after 1.5 s"));
    CHECK_THAT(results[1].reason, StartsWith("timed out after 0.5 s"));
    CHECK_THAT(results[1].reason, Contains("timed out on an earlier case"));
    CHECK_THAT(results[2].reason, StartsWith("timed out after 0.5 s"));
    static_assert(kMaxTimeoutsInARow == 3, "the cases below expect three timeouts before the rest is skipped");
    for (int i = 3; i < 5; ++i) {
        CHECK_THAT(results[i].reason, StartsWith("not run: the program timed out on 3 cases in a row"));
        CHECK_FALSE(results[i].timedOut);
        CHECK(results[i].seconds == 0.0);
        CHECK(results[i].maxPoints == 1);
    }
    for (const GradeResult& result : results) {
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.points == 0);
    }

    // A case that finishes in time breaks the streak: hang, hang, answer, hang, hang all run.
    std::vector<CaseJob> mixed = jobs;
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
    for (const GradeResult& result : results) CHECK_THAT(result.reason, Equals("timed out after 0.5 s"));
}
