// .mistake headers, and judging whether a mistake is caught.

#include "catch.hpp"

#include "MistakeCheck.hpp"
#include "MistakeFile.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>

using namespace stoa::grader;

namespace {

const char* const kMistake =
    "# a planted mistake\n"
    "hint: the view matrix is transposed: the scene turns the wrong way\n"
    "docs: labs/01_transforms.md#the-view-matrix\n"
    "fails:  orbit_front   orbit_side\n"
    "\n"
    "file: transforms.cpp\n"
    "--- find\n"
    "    return view;\n"
    "--- replace\n"
    "hint: not a header line any more\n"
    "--- end\n";

// The InputError's message for parsing `text` as "x.mistake".
stoa::InputError parseError(const std::string& text) {
    try {
        parseMistakeHeader(text, "x.mistake");
    } catch (const stoa::InputError& error) {
        return error;
    }
    FAIL("parseMistakeHeader accepted: " << text);
    return stoa::InputError("", 0, "");
}

GradeResult result(const std::string& name, GradeStatus status) {
    GradeResult r;
    r.lab = "01_transforms";
    r.caseName = name;
    r.status = status;
    r.reason = "why";
    return r;
}

} // namespace

TEST_CASE("parseMistakeHeader reads the header up to the first --- line", "[grader][mistake]") {
    MistakeFile mistake = parseMistakeHeader(kMistake, "solutions/01_transforms/mistakes/view_transposed.mistake");
    CHECK(mistake.name == "view_transposed");
    CHECK(mistake.hint == "the view matrix is transposed: the scene turns the wrong way");
    CHECK(mistake.docs == "labs/01_transforms.md#the-view-matrix");
    CHECK(mistake.fails == std::vector<std::string>{"orbit_front", "orbit_side"});
    CHECK(mistake.file == "transforms.cpp");
}

TEST_CASE("parseMistakeHeader: docs is optional", "[grader][mistake]") {
    MistakeFile mistake = parseMistakeHeader("hint: h\nfails: a\nfile: f.cpp\n--- find\n", "m.mistake");
    CHECK(mistake.docs.empty());
    CHECK(mistake.fails == std::vector<std::string>{"a"});
}

TEST_CASE("parseMistakeHeader rejects bad headers with file and line", "[grader][mistake]") {
    stoa::InputError noColon = parseError("hint: h\nfails a b\nfile: f\n");
    CHECK(noColon.file() == "x.mistake");
    CHECK(noColon.line() == 2);
    CHECK(std::string(noColon.what()).find("x.mistake:2:") == 0);

    stoa::InputError unknown = parseError("hint: h\nfails: a\nfile: f\nfial: b\n");
    CHECK(unknown.line() == 4);
    CHECK(unknown.message().find("unknown key 'fial'") != std::string::npos);

    stoa::InputError twice = parseError("hint: h\nhint: again\nfails: a\nfile: f\n");
    CHECK(twice.line() == 2);
    CHECK(twice.message().find("appears twice") != std::string::npos);

    stoa::InputError emptyFails = parseError("hint: h\nfails:\nfile: f\n");
    CHECK(emptyFails.line() == 2);

    stoa::InputError missingFails = parseError("hint: h\nfile: f\n--- find\nfails: a\n");
    CHECK(missingFails.line() == 0);
    CHECK(missingFails.message().find("fails:") != std::string::npos);

    stoa::InputError missingFile = parseError("hint: h\nfails: a\n");
    CHECK(missingFile.message().find("file:") != std::string::npos);

    stoa::InputError emptyHint = parseError("hint:\nfails: a\nfile: f\n");
    CHECK(emptyHint.message().find("hint") != std::string::npos);
}

TEST_CASE("loadMistakes reads a lab's mistakes in name order", "[grader][mistake]") {
    stoa::test::TempFolder folder;
    folder.write("solutions/01_transforms/mistakes/b_second.mistake", kMistake);
    folder.write("solutions/01_transforms/mistakes/a_first.mistake", "hint: h\nfails: x\nfile: f.cpp\n--- find\n");
    folder.write("solutions/01_transforms/mistakes/notes.txt", "not a mistake");
    std::vector<MistakeFile> mistakes = loadMistakes(folder.path() / "solutions/01_transforms");
    REQUIRE(mistakes.size() == 2);
    CHECK(mistakes[0].name == "a_first");
    CHECK(mistakes[0].lab == "01_transforms");
    CHECK(mistakes[1].name == "b_second");

    CHECK(loadMistakes(folder.path() / "solutions/02_none").empty());
    CHECK_THROWS_AS(loadMistakeFile(folder.path() / "missing.mistake"), stoa::InputError);
}

// A failed result whose known-mistake hint names `mistakeName`.
static GradeResult hinted(const std::string& name, const std::string& mistakeName) {
    GradeResult r = result(name, GradeStatus::Failed);
    r.hint = "the hint of " + mistakeName;
    r.hintMistake = mistakeName;
    return r;
}

TEST_CASE("judgeMistake: caught only when every listed case failed", "[grader][mistake]") {
    MistakeFile mistake = parseMistakeHeader(kMistake, "view_transposed.mistake");

    MistakeVerdict caught = judgeMistake(mistake, {hinted("orbit_front", "view_transposed"),
                                                   result("orbit_side", GradeStatus::Failed),
                                                   result("fly", GradeStatus::Passed)});
    CHECK(caught.caught);
    CHECK(caught.detail == "caught, hint ok");

    MistakeVerdict extra = judgeMistake(mistake, {result("orbit_front", GradeStatus::Failed),
                                                  hinted("orbit_side", "view_transposed"),
                                                  result("fly", GradeStatus::Failed)});
    CHECK(extra.caught);
    CHECK(extra.detail == "caught, hint ok (also fails fly)");

    MistakeVerdict passed = judgeMistake(mistake, {result("orbit_front", GradeStatus::Failed),
                                                   result("orbit_side", GradeStatus::Passed)});
    CHECK_FALSE(passed.caught);
    CHECK(passed.detail == "NOT caught: orbit_side passed");

    MistakeVerdict crashed = judgeMistake(mistake, {result("orbit_front", GradeStatus::Error),
                                                    result("orbit_side", GradeStatus::NotAttempted)});
    CHECK_FALSE(crashed.caught);
    CHECK(crashed.detail == "NOT caught: orbit_front is error: why; orbit_side is not attempted: why");

    MistakeVerdict missing = judgeMistake(mistake, {result("orbit_front", GradeStatus::Failed)});
    CHECK_FALSE(missing.caught);
    CHECK(missing.detail.find("orbit_side was not graded") != std::string::npos);
}

TEST_CASE("judgeMistake: caught also needs a hint that names the mistake", "[grader][mistake][hint]") {
    MistakeFile mistake = parseMistakeHeader(kMistake, "view_transposed.mistake");

    MistakeVerdict noHint = judgeMistake(mistake, {result("orbit_front", GradeStatus::Failed),
                                                   result("orbit_side", GradeStatus::Failed)});
    CHECK_FALSE(noHint.caught);
    CHECK(noHint.detail.find("no failed case's hint names this mistake (orbit_front: no hint; orbit_side: no hint)") !=
          std::string::npos);
    CHECK(noHint.detail.find("--update-references") != std::string::npos);

    MistakeVerdict other = judgeMistake(mistake, {hinted("orbit_front", "aspect_inverted"),
                                                  hinted("orbit_side", "aspect_inverted")});
    CHECK_FALSE(other.caught);
    CHECK(other.detail.find("orbit_front: hint names aspect_inverted") != std::string::npos);

    // A hint on a case the mistake does not list does not count.
    MistakeVerdict elsewhere = judgeMistake(mistake, {result("orbit_front", GradeStatus::Failed),
                                                      result("orbit_side", GradeStatus::Failed),
                                                      hinted("fly", "view_transposed")});
    CHECK_FALSE(elsewhere.caught);
}

TEST_CASE("judgeMistake: a failed property check stands in for a hint only when the mistake fails checks only",
          "[grader][mistake][hint]") {
    auto check = [](const std::string& name, GradeStatus status) {
        GradeResult entry = result(name, status);
        entry.propertyCheck = true;
        return entry;
    };
    // Fails a property check only: the check's message explains it, no gallery hint is needed.
    MistakeFile checksOnly = parseMistakeHeader("hint: h\ndocs: labs/05_shadows.md#texel-snapping\nfails: texel_snapping\n"
                                                "file: cascades.cpp\n",
                                                "no_texel_snapping.mistake");
    MistakeVerdict onlyCheck = judgeMistake(checksOnly, {check("texel_snapping", GradeStatus::Failed),
                                                         result("sun_columns", GradeStatus::Passed)});
    CHECK(onlyCheck.caught);

    // Fails a picture case too: that case still needs the hint naming the mistake.
    MistakeFile mixed = parseMistakeHeader("hint: h\ndocs: labs/01_transforms.md#cameras\nfails: orbit_tumbled camera_limits\n"
                                           "file: cameras.cpp\n",
                                           "tumble_pitch_inverted.mistake");
    MistakeVerdict noHint = judgeMistake(mixed, {result("orbit_tumbled", GradeStatus::Failed),
                                                 check("camera_limits", GradeStatus::Failed)});
    CHECK_FALSE(noHint.caught);
    CHECK(noHint.detail.find("orbit_tumbled: no hint") != std::string::npos);
    CHECK(noHint.detail.find("camera_limits") == std::string::npos);
    MistakeVerdict hinted2 = judgeMistake(mixed, {hinted("orbit_tumbled", "tumble_pitch_inverted"),
                                                  check("camera_limits", GradeStatus::Failed)});
    CHECK(hinted2.caught);
}
