// Known-mistake hints: the distance order, choosing the closest gallery image,
// reading the gallery, and hints added to failed results, with synthetic images.

#include "catch.hpp"

#include "Hints.hpp"

#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>

using namespace stoa::grader;
using stoa::Image;

namespace {

// addHints() over outcomes made of `jobs` and `results` (the same length), as
// a run hands them over; the results with their hints.
std::vector<GradeResult> hinted(const std::vector<CaseJob>& jobs, const std::vector<GradeResult>& results,
                                const HintGallery* gallery = nullptr, int parallelJobs = 1) {
    std::vector<CaseOutcome> outcomes;
    for (std::size_t i = 0; i < jobs.size(); ++i) outcomes.push_back(CaseOutcome{jobs[i], "", results[i], {}});
    if (gallery) addHints(outcomes, *gallery, parallelJobs);
    else addHints(outcomes, parallelJobs);
    return resultsOf(outcomes);
}

constexpr int kSize = 64;

// A dark image with a bright square of side 16 at (x, y).
Image squareAt(int x, int y, std::uint8_t level = 230) {
    Image image(kSize, kSize, 4);
    for (int row = 0; row < kSize; ++row)
        for (int column = 0; column < kSize; ++column) image.setPixel(column, row, {20, 30, 40, 255});
    for (int row = y; row < y + 16; ++row)
        for (int column = x; column < x + 16; ++column) image.setPixel(column, row, {level, level, level, 255});
    return image;
}

CompareMetrics metrics(double flip, double bad, double mean) { return CompareMetrics{bad, mean, 0, flip}; }

const char* const kInfo = "hint: The square is on the wrong side.\n"
                          "docs: labs/01_transforms.md#the-model-matrix\n"
                          "fails: front\n"
                          "file: transforms.cpp\n";

} // namespace

TEST_CASE("isCloser: FLIP when both have it, else bad pixels, then mean error", "[grader][hint]") {
    CHECK(isCloser(metrics(0.1, 0.5, 90), metrics(0.2, 0.1, 10)));        // FLIP decides
    CHECK_FALSE(isCloser(metrics(0.2, 0.1, 10), metrics(0.1, 0.5, 90)));
    CHECK(isCloser(metrics(-1, 0.1, 90), metrics(0.2, 0.5, 10)));         // one without FLIP: bad pixels
    CHECK(isCloser(metrics(0.3, 0.1, 9), metrics(0.3, 0.1, 10)));         // equal FLIP: bad, then mean
    CHECK(isCloser(metrics(-1, 0.1, 9), metrics(-1, 0.1, 10)));
    CHECK_FALSE(isCloser(metrics(-1, 0.1, 10), metrics(-1, 0.1, 10)));    // equal is not closer
}

TEST_CASE("closestMistake picks the gallery image nearest the student's", "[grader][hint]") {
    Image reference = squareAt(8, 24);
    KnownMistake right{"square_right", "right", "", {}, {}};
    KnownMistake low{"square_low", "low", "", {}, {}};
    std::vector<GalleryImage> gallery;
    gallery.push_back(GalleryImage{right, squareAt(40, 24)});
    gallery.push_back(GalleryImage{low, squareAt(8, 44)});

    // Exactly a mistake's picture, and one a few levels off it.
    CHECK(closestMistake(squareAt(40, 24), reference, gallery, {}) == std::optional<std::size_t>(0));
    CHECK(closestMistake(squareAt(8, 44, 200), reference, gallery, {}) == std::optional<std::size_t>(1));
    // Closer to the reference than to any mistake (a dimmer square in the right place): no hint.
    CHECK_FALSE(closestMistake(squareAt(8, 24, 120), reference, gallery, {}).has_value());
    // No gallery, or only images of another size: no hint.
    CHECK_FALSE(closestMistake(squareAt(40, 24), reference, {}, {}).has_value());
    std::vector<GalleryImage> wrongSize;
    wrongSize.push_back(GalleryImage{right, Image(32, 32, 4)});
    CHECK_FALSE(closestMistake(squareAt(40, 24), reference, wrongSize, {}).has_value());
    // A known reference distance is used as given: nothing beats a perfect one.
    CompareMetrics perfect{0.0, 0.0, 0, 0.0};
    CHECK_FALSE(closestMistake(squareAt(40, 24), reference, gallery, {}, perfect).has_value());
}

TEST_CASE("clearlyCloser: a third of the distance to the reference, or closer", "[grader][hint]") {
    CHECK(clearlyCloser(metrics(0.03, 0.5, 9), metrics(0.1, 0.5, 9)));
    CHECK_FALSE(clearlyCloser(metrics(0.05, 0.1, 9), metrics(0.1, 0.5, 9)));   // closer, not by the margin
    CHECK(clearlyCloser(metrics(0.0, 0.0, 0), metrics(0.2, 0.3, 9)));          // the very picture
    CHECK_FALSE(clearlyCloser(metrics(0.0, 0.0, 0), metrics(0.0, 0.0, 0)));    // nothing to be closer than
    CHECK(clearlyCloser(metrics(-1, 0.01, 9), metrics(-1, 0.3, 9)));           // without FLIP: bad pixels
}

TEST_CASE("patternAgrees: a case the mistake fails that passed rules it out", "[grader][hint]") {
    std::vector<std::string> fails = {"wide_lens", "first_person_walk"};
    using S = GradeStatus;
    CHECK(patternAgrees(fails, {{"wide_lens", S::Failed}, {"first_person_walk", S::Failed}, {"orbit_front", S::Passed}}));
    // walkRight's sign flipped fails first_person_walk only: aspect_inverted would fail wide_lens too.
    CHECK_FALSE(patternAgrees(fails, {{"wide_lens", S::Passed}, {"first_person_walk", S::Failed}}));
    // A failure the mistake does not explain (a second mistake, a hidden case) does not rule it out.
    CHECK(patternAgrees(fails, {{"wide_lens", S::Failed}, {"first_person_walk", S::Failed}, {"hidden", S::Failed}}));
    // Not attempted, errors and cases not graded say nothing.
    CHECK(patternAgrees(fails, {{"wide_lens", S::NotAttempted}, {"first_person_walk", S::Error}}));
}

TEST_CASE("addHints: a passed case the mistake fails, or one case not clearly closer, silences it",
          "[grader][hint]") {
    stoa::test::TempFolder folder("pattern");
    std::filesystem::path refs = folder / "references/01_transforms";
    std::filesystem::create_directories(refs / "mistakes/square_right");
    squareAt(8, 24).savePng(refs / "front.png");
    squareAt(8, 24).savePng(refs / "side.png");
    squareAt(40, 24).savePng(refs / "mistakes/square_right/front.png");
    squareAt(40, 44).savePng(refs / "mistakes/square_right/side.png");
    folder.write("references/01_transforms/mistakes/square_right/mistake.txt",
                 "hint: The square is on the wrong side.\nfails: front side\nfile: transforms.cpp\n");
    auto graded = [&](const std::string& caseName, GradeStatus status, const Image& rendered) {
        std::filesystem::path path = folder / (caseName + std::to_string(static_cast<int>(status)) + ".png");
        rendered.savePng(path);
        GradeResult result;
        result.lab = "01_transforms";
        result.caseName = caseName;
        result.status = status;
        result.renderedImage = path;
        return result;
    };
    CaseJob front;
    front.lab = "01_transforms";
    front.program = "student";
    front.spec.name = "front";
    front.reference = refs / "front.png";
    CaseJob side = front;
    side.spec.name = "side";
    side.reference = refs / "side.png";
    std::vector<CaseJob> jobs = {front, side};

    // Both cases look like the mistake: hints on both.
    std::vector<GradeResult> both = {graded("front", GradeStatus::Failed, squareAt(40, 24)),
                                     graded("side", GradeStatus::Failed, squareAt(40, 44))};
    both = hinted(jobs, both);
    CHECK(both[0].hintMistake == "square_right");
    CHECK(both[1].hintMistake == "square_right");
    // The same front picture, but side passed: the mistake would have failed it.
    std::vector<GradeResult> sidePassed = {graded("front", GradeStatus::Failed, squareAt(40, 24)),
                                           graded("side", GradeStatus::Passed, squareAt(8, 24))};
    sidePassed = hinted(jobs, sidePassed);
    CHECK_FALSE(sidePassed[0].hasHint());
    // Side failed but looks nothing like the mistake's side: silent on front too.
    std::vector<GradeResult> sideElse = {graded("front", GradeStatus::Failed, squareAt(40, 24)),
                                         graded("side", GradeStatus::Failed, squareAt(8, 4))};
    sideElse = hinted(jobs, sideElse);
    CHECK_FALSE(sideElse[0].hasHint());
    CHECK_FALSE(sideElse[1].hasHint());
}

TEST_CASE("docsPath puts docs/ before a .mistake file's docs: value", "[grader][hint]") {
    CHECK(docsPath("labs/01_transforms.md#the-view-matrix") == "docs/labs/01_transforms.md#the-view-matrix");
    CHECK(docsPath("docs/labs/02_shading.md") == "docs/labs/02_shading.md");
    CHECK(docsPath("/labs/02_shading.md") == "docs/labs/02_shading.md");
    CHECK(docsPath("").empty());
}

TEST_CASE("loadGallery reads each mistake's info file, sorted by name", "[grader][hint]") {
    stoa::test::TempFolder folder("gallery");
    MistakeFile mistake = parseMistakeHeader(kInfo, "square_right.mistake");
    mistake.lab = "01_transforms";
    std::string text = galleryInfoText(mistake, {"front", "side"});
    CHECK(text.find("solutions/01_transforms/mistakes/square_right.mistake") != std::string::npos);
    CHECK(parseMistakeHeader(text, "mistake.txt").fails == std::vector<std::string>{"front", "side"});

    folder.write("refs/mistakes/square_right/mistake.txt", text);
    folder.write("refs/mistakes/a_first/mistake.txt", kInfo);
    folder.write("refs/mistakes/no_info/front.png", "not read");
    std::vector<KnownMistake> gallery = loadGallery(folder / "refs");
    REQUIRE(gallery.size() == 2);
    CHECK(gallery[0].name == "a_first");
    CHECK(gallery[1].name == "square_right");
    CHECK(gallery[1].hint == "The square is on the wrong side.");
    CHECK(gallery[1].docs == "labs/01_transforms.md#the-model-matrix");
    CHECK(gallery[1].imageFor("front") == folder / "refs/mistakes/square_right/front.png");

    CHECK(loadGallery(folder / "nothing-here").empty());
    folder.write("refs/mistakes/broken/mistake.txt", "this is not a header\n");
    CHECK_THROWS_AS(loadGallery(folder / "refs"), stoa::InputError);
}

TEST_CASE("addHints names the mistake a failed case looks like", "[grader][hint]") {
    stoa::test::TempFolder folder("hints");
    std::filesystem::path refs = folder / "references/01_transforms";
    std::filesystem::create_directories(refs / "mistakes/square_right");
    std::filesystem::create_directories(refs / "mistakes/square_low");
    squareAt(8, 24).savePng(refs / "front.png");
    squareAt(40, 24).savePng(refs / "mistakes/square_right/front.png");
    folder.write("references/01_transforms/mistakes/square_right/mistake.txt", kInfo);
    squareAt(8, 44).savePng(refs / "mistakes/square_low/front.png");
    folder.write("references/01_transforms/mistakes/square_low/mistake.txt",
                 "hint: The square is too low.\nfails: front\nfile: transforms.cpp\n");

    auto failedCase = [&](const std::string& name, const Image& rendered) {
        std::filesystem::path path = folder / (name + ".png");
        rendered.savePng(path);
        GradeResult result;
        result.lab = "01_transforms";
        result.caseName = "front";
        result.status = stoa::grader::GradeStatus::Failed;
        result.renderedImage = path;
        return result;
    };
    CaseJob job;
    job.lab = "01_transforms";
    job.spec.name = "front";
    job.reference = refs / "front.png";

    std::vector<GradeResult> results = {failedCase("right", squareAt(40, 24, 220)),
                                        failedCase("low", squareAt(8, 44)),
                                        failedCase("dim", squareAt(8, 24, 120)),
                                        failedCase("passed", squareAt(40, 24))};
    results[3].status = GradeStatus::Passed;
    // Each result from its own program: rule (b) judges a program's cases together.
    std::vector<CaseJob> jobs = {job, job, job, job};
    for (std::size_t i = 0; i < jobs.size(); ++i) jobs[i].program = "program" + std::to_string(i);
    HintGallery gallery = HintGallery::load(jobs);
    CHECK(gallery.imageCount() == 2);   // once per reference, however many jobs share it
    CaseJob elsewhere = job;
    elsewhere.reference = folder / "elsewhere/front.png";
    CHECK(gallery.imagesFor(elsewhere).empty());
    // The gallery is read before grading: removing it afterwards changes nothing.
    std::filesystem::remove_all(refs / "mistakes");
    results = hinted(jobs, results, &gallery, 2);

    CHECK(results[0].hintMistake == "square_right");
    CHECK(results[0].hint == "The square is on the wrong side.");
    CHECK(results[0].hintDocs == "docs/labs/01_transforms.md#the-model-matrix");
    CHECK(results[0].hintImage == refs / "mistakes/square_right/front.png");
    CHECK(results[0].hintDistance >= 0.0);
    CHECK(results[0].hintDistance < 0.05);
    CHECK(results[1].hintMistake == "square_low");
    CHECK(results[1].hintDocs.empty());
    CHECK_FALSE(results[2].hasHint());
    CHECK_FALSE(results[3].hasHint());   // only failed cases get hints

    // The distance grading measured is used when present: a perfect one leaves no mistake closer.
    std::vector<GradeResult> measured = {failedCase("right4", squareAt(40, 24))};
    measured[0].metrics = CompareMetrics{0.0, 0.0, 0, 0.0};
    measured = hinted({job}, measured, &gallery);
    CHECK_FALSE(measured[0].hasHint());

    // Restore the gallery on disk for the rest.
    std::filesystem::create_directories(refs / "mistakes/square_right");
    squareAt(40, 24).savePng(refs / "mistakes/square_right/front.png");
    folder.write("references/01_transforms/mistakes/square_right/mistake.txt", kInfo);

    // A case without gallery images, and a gallery that does not parse: no hint, no exception.
    std::vector<GradeResult> other = {failedCase("right2", squareAt(40, 24))};
    other[0].caseName = "side";
    CaseJob side = job;
    side.spec.name = "side";
    other = hinted({side}, other);
    CHECK_FALSE(other[0].hasHint());
    folder.write("references/01_transforms/mistakes/broken/mistake.txt", "garbage\n");
    std::vector<GradeResult> again = {failedCase("right3", squareAt(40, 24))};
    CHECK_NOTHROW(again = hinted({job}, again));
    CHECK_FALSE(again[0].hasHint());
}
