// One case graded end to end, with a shell script as the "lab program": it
// copies a prepared PNG to the --output path, or misbehaves on purpose.

#include "catch.hpp"

#include "CaseRunner.hpp"
#include "Grader.hpp"
#include "ReferenceGuard.hpp"
#include "TempFolder.hpp"

#include <stoa/image/Image.hpp>

#include <atomic>
#include <chrono>
#include <fstream>
#include <functional>
#include <iterator>
#include <thread>

using namespace stoa::grader;
using stoa::Image;

namespace {

Image gradient(int width, int height, int shift = 0) {
    Image image(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.setPixel(x, y, {static_cast<std::uint8_t>((x * 16 + shift) & 255),
                                  static_cast<std::uint8_t>(y * 16), 128, 255});
    return image;
}

struct Fixture {
    stoa::test::TempFolder folder;
    RunSettings settings;

    Fixture() { settings.limits = defaultLimits(5.0); }

    // A lab program whose body runs with $2 = case name and $4 = output path.
    std::filesystem::path program(const std::string& name, const std::string& body) {
        return folder.write("bin/" + name, "#!/bin/sh\n" + body + "\n", true);
    }

    CaseJob job(const std::filesystem::path& program, const std::string& reference = "reference.png") {
        CaseJob job;
        job.lab = "01_transforms";
        job.program = program;
        job.spec.name = "orbit_front";
        job.spec.width = 16;
        job.spec.height = 16;
        job.spec.points = 10;
        job.reference = folder.path() / reference;
        job.workDir = folder.path() / "work" / job.lab / job.spec.name;
        return job;
    }
};

} // namespace

TEST_CASE("gradeCase: an image that matches the reference passes and earns the points", "[grader][case]") {
    Fixture fixture;
    gradient(16, 16).savePng(fixture.folder.path() / "reference.png");
    gradient(16, 16).savePng(fixture.folder.path() / "student.png");
    auto program = fixture.program("lab01_transforms", "cp '" + (fixture.folder.path() / "student.png").string() +
                                                           "' \"$4\"");
    GradeResult result = gradeCase(fixture.job(program), fixture.settings);
    CHECK(result.status == GradeStatus::Passed);
    CHECK(result.points == 10);
    CHECK(result.maxPoints == 10);
    CHECK(result.fullName() == "01_transforms/orbit_front");
    CHECK(result.renderedImage == fixture.folder.path() / "work/01_transforms/orbit_front/rendered.png");
    CHECK(result.heatMapImage.empty());
}

TEST_CASE("gradeCase: an image that differs fails and leaves a heat map", "[grader][case]") {
    Fixture fixture;
    gradient(16, 16).savePng(fixture.folder.path() / "reference.png");
    gradient(16, 16, 128).savePng(fixture.folder.path() / "student.png");
    auto program = fixture.program("lab01_transforms", "cp '" + (fixture.folder.path() / "student.png").string() +
                                                           "' \"$4\"");
    GradeResult result = gradeCase(fixture.job(program), fixture.settings);
    CHECK(result.status == GradeStatus::Failed);
    CHECK(result.points == 0);
    CHECK_FALSE(result.reason.empty());
    REQUIRE_FALSE(result.heatMapImage.empty());
    CHECK(Image::load(result.heatMapImage).width() == 16);
    CHECK(std::filesystem::exists(result.renderedImage));
}

TEST_CASE("gradeCase: each way a render can go wrong has its status and reason", "[grader][case]") {
    Fixture fixture;
    gradient(16, 16).savePng(fixture.folder.path() / "reference.png");
    gradient(8, 4).savePng(fixture.folder.path() / "small.png");

    SECTION("exit 3 is not attempted, with the stub's name") {
        auto program = fixture.program("stub", "echo 'stoa: not implemented: Camera::viewMatrix()' >&2; exit 3");
        GradeResult result = gradeCase(fixture.job(program), fixture.settings);
        CHECK(result.status == GradeStatus::NotAttempted);
        CHECK(result.reason == "not implemented: Camera::viewMatrix()");
        CHECK(result.points == 0);
    }
    SECTION("a crash names the signal") {
        auto program = fixture.program("crash", "kill -SEGV $$");
        GradeResult result = gradeCase(fixture.job(program), fixture.settings);
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.reason.find("crashed with SIGSEGV") != std::string::npos);
    }
    SECTION("a nonzero exit quotes the last line") {
        auto program = fixture.program("fails", "echo 'shaders/x.glsl:3: syntax error' >&2; exit 1");
        GradeResult result = gradeCase(fixture.job(program), fixture.settings);
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.reason == "exited with status 1: shaders/x.glsl:3: syntax error");
    }
    SECTION("a timeout") {
        fixture.settings.limits = defaultLimits(1.0);
        auto program = fixture.program("slow", "sleep 20");
        GradeResult result = gradeCase(fixture.job(program), fixture.settings);
        CHECK(result.status == GradeStatus::Error);
        // A sleep uses no processor time: waiting, not computing.
        CHECK(result.reason ==
              "timed out after 1 s without computing (0.0 s of processor time): it waits for something that does "
              "not come (a hang)");
        CHECK_FALSE(result.busyWhenStopped);
    }
    SECTION("no image written") {
        auto program = fixture.program("lazy", "exit 0");
        GradeResult result = gradeCase(fixture.job(program), fixture.settings);
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.reason.find("wrote no image") != std::string::npos);
    }
    SECTION("an image that does not decode") {
        auto program = fixture.program("garbage", "echo 'not a png' > \"$4\"");
        GradeResult result = gradeCase(fixture.job(program), fixture.settings);
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.reason.find("does not decode") != std::string::npos);
    }
    SECTION("the wrong size") {
        auto program = fixture.program("small", "cp '" + (fixture.folder.path() / "small.png").string() + "' \"$4\"");
        GradeResult result = gradeCase(fixture.job(program), fixture.settings);
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.reason == "rendered 8x4, expected 16x16");
    }
    SECTION("no reference image") {
        gradient(16, 16).savePng(fixture.folder.path() / "student.png");
        auto program = fixture.program("good", "cp '" + (fixture.folder.path() / "student.png").string() + "' \"$4\"");
        GradeResult result = gradeCase(fixture.job(program, "missing.png"), fixture.settings);
        CHECK(result.status == GradeStatus::NoReference);
        CHECK(result.reason ==
              "no reference image: run stoa-grade --update-references from a solutions build");
        CHECK(result.points == 0);
    }
    SECTION("a program that is not there") {
        GradeResult result = gradeCase(fixture.job(fixture.folder.path() / "bin/none"), fixture.settings);
        CHECK(result.status == GradeStatus::Error);
        CHECK(result.reason.find("could not start") != std::string::npos);
    }
}

TEST_CASE("gradeCase: the program gets --render, --output and --backend", "[grader][case]") {
    Fixture fixture;
    fixture.settings.backend = "egl";
    auto program = fixture.program("args", "echo \"$@\" > args.txt; exit 3");
    CaseJob job = fixture.job(program);
    gradeCase(job, fixture.settings);
    std::ifstream file(job.workDir / "args.txt");
    std::string line;
    std::getline(file, line);
    CHECK(line == "--render orbit_front --output " + (job.workDir / "rendered.png").string() + " --backend egl");
}

TEST_CASE("gradeCases keeps the order of the jobs and reports progress", "[grader][case]") {
    Fixture fixture;
    auto program = fixture.program("stub", "sleep 0.$(( $(echo \"$2\" | wc -c) % 3 )); exit 3");
    std::vector<CaseJob> jobs;
    for (const char* name : {"a", "bb", "ccc", "dddd"}) {
        CaseJob job = fixture.job(program);
        job.spec.name = name;
        job.workDir = fixture.folder.path() / "work" / name;
        jobs.push_back(job);
    }
    std::vector<std::string> lines;
    std::vector<GradeResult> results = gradeCases(jobs, fixture.settings, 3,
        [&](std::size_t index, const GradeResult& result, std::size_t done, std::size_t total) {
            CHECK(result.caseName == jobs[index].spec.name);
            lines.push_back(progressLine(result, done, total));
        });
    REQUIRE(results.size() == 4);
    CHECK(results[0].caseName == "a");
    CHECK(results[3].caseName == "dddd");
    REQUIRE(lines.size() == 4);
    CHECK(lines.back().rfind("[4/4] 01_transforms/", 0) == 0);
    // The work folders lie beside the reference here, in the folder the reference
    // guard watches: the first case to end once removed them all as "appeared",
    // failing itself and, now and then, a case about to enter its own.
    for (const GradeResult& result : results) {
        INFO(result.caseName << ": " << result.reason);
        CHECK(result.status == GradeStatus::NotAttempted);
    }
}

TEST_CASE("The reference guard removes what appears beside a reference, except the way to a work folder",
          "[grader][case]") {
    Fixture fixture;
    gradient(16, 16).savePng(fixture.folder.path() / "reference.png");
    const std::filesystem::path work = fixture.folder.path() / "work" / "01_transforms" / "orbit_front";
    ReferenceGuard guard({fixture.folder.path() / "reference.png"}, {work});
    std::filesystem::create_directories(work);
    fixture.folder.write("work/01_transforms/orbit_front/rendered.png", "a picture");
    fixture.folder.write("forged.png", "not a reference");
    gradient(16, 16, 128).savePng(fixture.folder.path() / "reference.png");

    std::vector<std::filesystem::path> changed = guard.verifyAndRestore();
    REQUIRE(changed.size() == 2);
    CHECK(changed[0].filename() == "forged.png");
    CHECK(changed[1].filename() == "reference.png");
    CHECK_FALSE(std::filesystem::exists(fixture.folder.path() / "forged.png"));
    CHECK(Image::load(fixture.folder.path() / "reference.png").pixel(8, 0) == gradient(16, 16).pixel(8, 0));
    CHECK(std::filesystem::exists(work / "rendered.png"));
    CHECK(guard.verifyAndRestore().empty());
}

TEST_CASE("The reference guard blames the case that changed a reference, not the one beside it that ended first",
          "[grader][case]") {
    Fixture fixture;
    const std::filesystem::path reference = fixture.folder.path() / "reference.png";
    gradient(16, 16).savePng(reference);
    auto bytesOf = [&] {
        std::ifstream file(reference, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    };
    const std::string original = bytesOf();
    ReferenceGuard guard({reference}, {});
    std::atomic<bool> written{false};
    auto restored = [&] { return bytesOf() == original; };
    auto waitFor = [](const std::function<bool()>& condition) {
        for (int i = 0; i < 5000 && !condition(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return condition();
    };
    // The guilty case overwrites the reference and ends only after the innocent
    // one, which ended first, has found the change (and restored the file).
    int guiltyRuns = 0, innocentRuns = 0;
    bool innocentSawTheWrite = false, guiltySawTheRestore = false;
    std::vector<std::filesystem::path> guilty, innocent;
    std::thread guiltyCase([&] {
        guilty = guard.runAndVerify([&] {
            gradient(16, 16, 128).savePng(reference);
            if (guiltyRuns++ == 0) {
                written = true;
                guiltySawTheRestore = waitFor(restored);
            }
        });
    });
    std::thread innocentCase([&] {
        innocent = guard.runAndVerify([&] {
            if (innocentRuns++ == 0) innocentSawTheWrite = waitFor([&] { return written.load(); });
        });
    });
    guiltyCase.join();
    innocentCase.join();
    REQUIRE(innocentSawTheWrite);
    REQUIRE(guiltySawTheRestore);
    // Both ran beside a change, so both ran again alone: only the guilty one changed the reference then.
    CHECK(innocentRuns == 2);
    CHECK(guiltyRuns == 2);
    CHECK(innocent.empty());
    REQUIRE(guilty.size() == 1);
    CHECK(guilty[0].filename() == "reference.png");
    CHECK(restored());
    // A case that runs alone is run once, blamed or not.
    int runs = 0;
    CHECK(guard.runAndVerify([&] { ++runs; }).empty());
    CHECK(guard.runAndVerify([&] { ++runs; gradient(16, 16, 128).savePng(reference); }).size() == 1);
    CHECK(runs == 2);
    CHECK(restored());
}

TEST_CASE("gradeCase: a property check is graded by its exit status and says why", "[grader][case]") {
    Fixture fixture;
    auto check = [&](const std::string& body) {
        CaseJob job = fixture.job(fixture.program("lab05_shadows", body), "no-reference-for-a-check.png");
        job.spec.check = "texel_snapping";
        job.spec.name = "texel_snapping";
        return gradeCase(job, fixture.settings);
    };

    GradeResult holds = check("echo \"check $2: holds: the map moves by whole texels\"; exit 0");
    CHECK(holds.status == GradeStatus::Passed);
    CHECK(holds.points == 10);
    CHECK(holds.propertyCheck);
    CHECK(holds.reason == "holds: the map moves by whole texels");
    CHECK(holds.referenceImage.empty());

    GradeResult fails = check("echo \"check $2: does not hold: moved by 0.32 texels\"; exit 4");
    CHECK(fails.status == GradeStatus::Failed);
    CHECK(fails.points == 0);
    CHECK(fails.reason == "does not hold: moved by 0.32 texels");
    CHECK(fails.renderedImage.empty());

    GradeResult stub = check("echo 'stoa: not implemented: cascadeLightMatrix()' >&2; exit 3");
    CHECK(stub.status == GradeStatus::NotAttempted);
    CHECK(stub.reason == "not implemented: cascadeLightMatrix()");

    GradeResult crash = check("kill -SEGV $$");
    CHECK(crash.status == GradeStatus::Error);
    CHECK(crash.points == 0);
}
