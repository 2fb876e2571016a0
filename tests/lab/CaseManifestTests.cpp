// Case manifests: the parser reads the typed keys and keeps the others for the
// lab; every mistake in a manifest is an InputError with the file and the line.

#include "catch.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

using stoa::CaseKey;
using stoa::caseKeys;
using stoa::CaseSpec;
using stoa::findCaseKey;
using stoa::InputError;
using stoa::LabManifest;
using stoa::loadManifest;
using stoa::parseManifest;
using stoa::Visibility;

namespace {

const std::string kDataDir = std::string(STOA_TEST_DATA_DIR) + "/lab";

template <typename Function>
std::optional<InputError> inputErrorFrom(Function&& function) {
    try {
        function();
    } catch (const InputError& error) {
        return error;
    }
    return std::nullopt;
}

std::optional<InputError> parseError(const std::string& text) {
    return inputErrorFrom([&] { parseManifest(text, "cases.ini"); });
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A valid start that the error cases below build on (lines 1 to 3).
const std::string kHead = "lab = 01_transforms\n"
                          "title = Transforms\n"
                          "[case a]\n";

// One case with the given scene parameters, starting at line 2.
CaseSpec caseWith(const std::string& lines) {
    const LabManifest manifest = parseManifest("lab = 01_test\n[case test]\n" + lines, "cases.ini");
    return manifest.cases.at(0);
}

// A getter call that must throw InputError at `line` of cases.ini with `message`.
struct BadRead {
    std::function<void()> read;
    int line;
    std::string message;
};

template <std::size_t N>
void checkBadReads(const BadRead (&bad)[N]) {
    for (const BadRead& each : bad) {
        INFO(each.message);
        const auto error = inputErrorFrom(each.read);
        REQUIRE(error);
        CHECK(error->file() == "cases.ini");
        CHECK(error->line() == each.line);
        CHECK(error->message() == each.message);
    }
}

} // namespace

TEST_CASE("loadManifest: reads a complete manifest", "[lab][manifest]") {
    const LabManifest manifest = loadManifest(kDataDir + "/valid_cases.ini");
    CHECK(manifest.lab == "01_transforms");
    CHECK(manifest.title == "Transforms and cameras");
    CHECK(manifest.file == kDataDir + "/valid_cases.ini");
    REQUIRE(manifest.cases.size() == 2);
    CHECK(manifest.caseNames() == "orbit_front, first-person_2");

    const CaseSpec& front = manifest.cases[0];
    CHECK(front.name == "orbit_front");
    CHECK(front.description == "The test scene from the orbit camera");
    CHECK(front.width == 512);
    CHECK(front.height == 384);
    CHECK(front.points == 10.0);
    CHECK(front.visibility == Visibility::Visible);
    CHECK(front.compare.tolerance == 12);
    CHECK(front.compare.maxBadFraction == 0.002);
    CHECK(front.compare.searchRadius == stoa::CompareOptions().searchRadius);
    CHECK(front.file == manifest.file);
    CHECK(front.line == 5);
    CHECK(front.getString("camera") == "orbit");
    CHECK(front.getVec3("target") == glm::vec3(0.0f, 0.5f, 0.0f));
    CHECK(front.getNumber("distance") == 6.0);
    CHECK(front.getInt("samples") == 4);
    CHECK_FALSE(front.has("position"));
    CHECK_NOTHROW(front.requireAllKeysUsed());

    const CaseSpec& second = manifest.cases[1];
    CHECK(second.name == "first-person_2");
    CHECK(second.line == 17);
    CHECK(second.description == "Walking, seen from eye height");
    CHECK(second.width == 256);
    CHECK(second.height == 256);
    CHECK(second.points == 2.5);
    CHECK(second.visibility == Visibility::Hidden);
    CHECK(second.compare.tolerance == stoa::CompareOptions().tolerance);
    CHECK(second.compare.maxBadFraction == stoa::CompareOptions().maxBadFraction);
    CHECK(second.getVec3("position") == glm::vec3(1.0f, 1.5f, -4.25f));

    CHECK(manifest.find("first-person_2") == &manifest.cases[1]);
    CHECK(manifest.find("orbit") == nullptr);
}

TEST_CASE("loadManifest: a missing file or a folder is an InputError", "[lab][manifest]") {
    const auto missing = inputErrorFrom([] { loadManifest(kDataDir + "/no_such_cases.ini"); });
    REQUIRE(missing);
    CHECK(missing->file() == kDataDir + "/no_such_cases.ini");
    CHECK(missing->line() == 0);
    CHECK(missing->message() == "cannot open file");

    const auto folder = inputErrorFrom([] { loadManifest(kDataDir); });
    REQUIRE(folder);
    CHECK(contains(folder->message(), "cannot open file"));
}

TEST_CASE("parseManifest: defaults, comments, blank lines and Windows line ends", "[lab][manifest]") {
    const LabManifest manifest = parseManifest("\r\n# only a comment\r\nlab = 02_shading\r\n\r\n[case plain]\r\n"
                                               "   \t\r\n[ case  spaced ]  # comment\r\ncolour = red\r\n",
                                               "cases.ini");
    CHECK(manifest.lab == "02_shading");
    CHECK(manifest.title.empty());
    CHECK(manifest.file == "cases.ini");
    REQUIRE(manifest.cases.size() == 2);
    const CaseSpec& plain = manifest.cases[0];
    CHECK(plain.description.empty());
    CHECK(plain.width == 512);
    CHECK(plain.height == 512);
    CHECK(plain.points == 1.0);
    CHECK(plain.visibility == Visibility::Visible);
    CHECK(plain.line == 5);
    CHECK(manifest.cases[1].name == "spaced");
    CHECK(manifest.cases[1].line == 7);
    CHECK(manifest.cases[1].getString("colour") == "red");
}

TEST_CASE("parseManifest: every mistake names the file and the line", "[lab][manifest]") {
    struct Mistake {
        std::string text;
        int line;
        std::string message;
    };
    const Mistake mistakes[] = {
        {"lab = 01\nauthor = me\n[case a]\n", 2, "unknown lab-level key 'author'"},
        {"lab = 01\ncamera = orbit\n[case a]\n", 2, "unknown lab-level key 'camera'"},
        {"lab = 01\nresolution = 64 64\n[case a]\n", 2, "key 'resolution' is outside any [case NAME] section"},
        {"lab = 01\nlab = 02\n[case a]\n", 2, "duplicate key 'lab' (first at line 1)"},
        {"lab =\n[case a]\n", 1, "expected 'lab = NAME'"},
        {kHead + "just words\n", 4, "expected 'key = value', got 'just words'"},
        {kHead + "= 5\n", 4, "expected a key before '='"},
        {kHead + "max bad fraction = 0.1\n", 4, "bad key 'max bad fraction'"},
        {kHead + "[case b\n", 4, "expected '[case NAME]', got '[case b'"},
        {kHead + "[section b]\n", 4, "expected '[case NAME]', got '[section b]'"},
        {kHead + "[caseb]\n", 4, "expected '[case NAME]'"},
        {kHead + "[case]\n", 4, "expected '[case NAME]' with a name"},
        {kHead + "[case orbit front]\n", 4, "bad case name 'orbit front': use letters, digits, '_' and '-'"},
        {kHead + "[case a.b]\n", 4, "bad case name 'a.b'"},
        {kHead + "\n[case a]\n", 5, "duplicate case 'a' (first at line 3)"},
        {kHead + "points = 1\ncamera = x\npoints = 2\n", 6, "duplicate key 'points' in case 'a' (first at line 4)"},
        {kHead + "camera = x\n\ncamera = y\n", 6, "duplicate key 'camera' in case 'a' (first at line 4)"},
        {kHead + "resolution = 512\n", 4, "expected 'resolution = WIDTH HEIGHT' with two whole numbers from 1 to 4096, got '512'"},
        {kHead + "resolution = 512 384 3\n", 4, "got '512 384 3'"},
        {kHead + "resolution = 0 384\n", 4, "got '0 384'"},
        {kHead + "resolution = 512 -1\n", 4, "got '512 -1'"},
        {kHead + "resolution = 4097 16\n", 4, "got '4097 16'"},
        {kHead + "resolution = 51.2 384\n", 4, "got '51.2 384'"},
        {kHead + "resolution = 512x384\n", 4, "got '512x384'"},
        {kHead + "points = -1\n", 4, "expected a number of points >= 0, got '-1'"},
        {kHead + "points = ten\n", 4, "got 'ten'"},
        {kHead + "visibility = secret\n", 4, "expected 'visible' or 'hidden' for 'visibility', got 'secret'"},
        {kHead + "tolerance = 256\n", 4, "expected a tolerance from 0 to 255 levels (a whole number), got '256'"},
        {kHead + "tolerance = -1\n", 4, "got '-1'"},
        {kHead + "tolerance = 1.5\n", 4, "got '1.5'"},
        {kHead + "max_bad_fraction = 1.5\n", 4, "expected a max_bad_fraction from 0 to 1, got '1.5'"},
        {kHead + "max_bad_fraction = -0.1\n", 4, "got '-0.1'"},
        {kHead + "max_bad_fraction = 1%\n", 4, "got '1%'"},
        {kHead + "max_flip_mean = 2\n", 4, "expected a max_flip_mean from 0 to 1 (a mean LDR-FLIP error), got '2'"},
        {"title = No lab\n[case a]\n", 0, "missing 'lab = NAME'"},
        {"lab = 01\n# no cases\n", 0, "no [case ...] sections"},
        {"", 0, "missing 'lab = NAME'"},
    };
    for (const Mistake& mistake : mistakes) {
        INFO("manifest:\n" << mistake.text);
        const auto error = parseError(mistake.text);
        REQUIRE(error);
        CHECK(error->file() == "cases.ini");
        CHECK(error->line() == mistake.line);
        CHECK(contains(error->message(), mistake.message));
        const std::string where = mistake.line > 0 ? "cases.ini:" + std::to_string(mistake.line) + ": " : "cases.ini: ";
        CHECK(std::string(error->what()).rfind(where, 0) == 0);
    }
}

TEST_CASE("parseManifest: boundary values that are allowed", "[lab][manifest]") {
    const LabManifest manifest = parseManifest(kHead + "resolution = 4096 1\npoints = 0\ntolerance = 0\n"
                                                       "max_bad_fraction = 1\nmax_flip_mean = 1\n[case b]\n"
                                                       "tolerance = 255\nmax_bad_fraction = 0\nmax_flip_mean = 0\n"
                                                       "lab = a scene parameter here\n",
                                               "cases.ini");
    const CaseSpec& a = manifest.cases.at(0);
    CHECK(a.width == 4096);
    CHECK(a.height == 1);
    CHECK(a.points == 0.0);
    CHECK(a.compare.tolerance == 0);
    CHECK(a.compare.maxBadFraction == 1.0);
    CHECK(a.compare.maxFlipMean == 1.0);
    const CaseSpec& b = manifest.cases.at(1);
    CHECK(b.compare.tolerance == 255);
    CHECK(b.compare.maxBadFraction == 0.0);
    CHECK(b.compare.maxFlipMean == 0.0);
    CHECK(b.getString("lab") == "a scene parameter here");
}

TEST_CASE("CaseSpec getters: values, fallbacks and errors with the key's line", "[lab][manifest]") {
    const CaseSpec spec = caseWith("distance = 2.5\n"     // line 3
                                   "bad_number = 1.5x\n"  // line 4
                                   "count = -7\n"         // line 5
                                   "fraction = 0.5\n"     // line 6
                                   "target = 1 -2 3e-1\n" // line 7
                                   "short = 1 2\n"        // line 8
                                   "long = 1 2 3 4\n"     // line 9
                                   "words = a b c\n"      // line 10
                                   "empty =\n"            // line 11
                                   "plus = +3\n");        // line 12
    CHECK(spec.getNumber("distance") == 2.5);
    CHECK(spec.getNumber("count") == -7.0);
    CHECK(spec.getInt("count") == -7);
    CHECK(spec.getInt("plus") == 3);
    CHECK(spec.getVec3("target") == glm::vec3(1.0f, -2.0f, 0.3f));
    CHECK(spec.getString("empty").empty());
    CHECK(spec.getString("words") == "a b c");

    // Fallbacks apply only to missing keys.
    CHECK(spec.getNumber("missing", 4.0) == 4.0);
    CHECK(spec.getInt("missing", 9) == 9);
    CHECK(spec.getString("missing", std::string("x")) == "x");
    CHECK(spec.getVec3("missing", glm::vec3(1.0f)) == glm::vec3(1.0f));
    CHECK(spec.getNumber("distance", 9.0) == 2.5);

    const BadRead bad[] = {
        {[&] { spec.getNumber("bad_number"); }, 4, "expected a number for 'bad_number', got '1.5x'"},
        {[&] { spec.getNumber("bad_number", 1.0); }, 4, "expected a number for 'bad_number', got '1.5x'"},
        {[&] { spec.getNumber("empty"); }, 11, "expected a number for 'empty', got ''"},
        {[&] { spec.getNumber("words"); }, 10, "expected a number for 'words', got 'a b c'"},
        {[&] { spec.getInt("fraction"); }, 6, "expected an integer for 'fraction', got '0.5'"},
        {[&] { spec.getInt("distance", 1); }, 3, "expected an integer for 'distance', got '2.5'"},
        {[&] { spec.getVec3("short"); }, 8, "expected three numbers for 'short', got '1 2'"},
        {[&] { spec.getVec3("long"); }, 9, "expected three numbers for 'long', got '1 2 3 4'"},
        {[&] { spec.getVec3("words"); }, 10, "expected three numbers for 'words', got 'a b c'"},
        {[&] { spec.getString("missing"); }, 2, "case 'test' needs a 'missing = ...' line"},
        {[&] { spec.getNumber("missing"); }, 2, "case 'test' needs a 'missing = NUMBER' line"},
        {[&] { spec.getInt("missing"); }, 2, "case 'test' needs a 'missing = INTEGER' line"},
        {[&] { spec.getVec3("missing"); }, 2, "case 'test' needs a 'missing = X Y Z' line"},
    };
    checkBadReads(bad);
}

TEST_CASE("CaseSpec checked getters: ranges, lists of numbers, choices and switches", "[lab][manifest]") {
    const CaseSpec spec = caseWith("cascades = 4\n"                 // line 3
                                   "too_many = 7\n"                 // line 4
                                   "lambda = 0.75\n"                // line 5
                                   "too_big = 1.5\n"                // line 6
                                   "sun = 1 -2 0.5  1 0.9 0.8\n"    // line 7
                                   "five = 1 2 3 4 5\n"             // line 8
                                   "seven = 1 2 3 4 5 6 7\n"        // line 9
                                   "letter = 1 2 3 4 5 x\n"         // line 10
                                   "pcf = 3x3\n"                    // line 11
                                   "bad_pcf = bilinear\n"           // line 12
                                   "shadows = off\n"                // line 13
                                   "bad_switch = yes\n");           // line 14
    CHECK(spec.getIntInRange("cascades", 0, 4) == 4);
    CHECK(spec.getIntInRange("missing", 0, 4, 9) == 9);  // the fallback is the lab's, not checked
    CHECK(spec.getNumberInRange("lambda", 0.0, 1.0) == 0.75);
    CHECK(spec.getNumbers("sun", 6, "direction, colour") == std::vector<float>{1.0f, -2.0f, 0.5f, 1.0f, 0.9f, 0.8f});
    CHECK(spec.getChoice("pcf", {"single", "2x2", "3x3"}) == "3x3");
    CHECK(spec.getChoice("missing", {"single", "2x2"}, std::string("single")) == "single");
    CHECK_FALSE(spec.getSwitch("shadows", true));
    CHECK(spec.getSwitch("missing", true));

    const BadRead bad[] = {
        {[&] { spec.getIntInRange("too_many", 0, 4); }, 4, "expected an integer from 0 to 4 for 'too_many', got '7'"},
        {[&] { spec.getIntInRange("too_many", 0, 4, 0); }, 4, "expected an integer from 0 to 4 for 'too_many', got '7'"},
        {[&] { spec.getNumberInRange("too_big", 0.0, 1.0); }, 6, "expected a number from 0 to 1 for 'too_big', got '1.5'"},
        {[&] { spec.getNumberInRange("lambda", 0.8, 2.5); }, 5, "expected a number from 0.8 to 2.5 for 'lambda', got '0.75'"},
        {[&] { spec.getNumbers("five", 6, "direction x y z, colour r g b"); }, 8,
         "expected six numbers (direction x y z, colour r g b) for 'five', got '1 2 3 4 5'"},
        {[&] { spec.getNumbers("seven", 6, "direction x y z, colour r g b"); }, 9,
         "expected six numbers (direction x y z, colour r g b) for 'seven', got '1 2 3 4 5 6 7'"},
        {[&] { spec.getNumbers("letter", 6, ""); }, 10, "expected six numbers for 'letter', got '1 2 3 4 5 x'"},
        {[&] { spec.getNumbers("missing", 2, "near far"); }, 2,
         "case 'test' needs a 'missing = ...' line with two numbers (near far)"},
        {[&] { spec.getChoice("bad_pcf", {"single", "2x2", "3x3"}); }, 12,
         "expected single, 2x2 or 3x3 for 'bad_pcf', got 'bilinear'"},
        {[&] { spec.getSwitch("bad_switch", false); }, 14, "expected on or off for 'bad_switch', got 'yes'"},
        {[&] { spec.reject("pcf", "pcf needs shadows"); }, 11, "case 'test': pcf needs shadows"},
        {[&] { spec.reject("missing", "something is wrong"); }, 2, "case 'test': something is wrong"},
    };
    checkBadReads(bad);
}

TEST_CASE("CaseSpec: numbers do not depend on odd spellings", "[lab][manifest]") {
    const CaseSpec spec = caseWith("a = 1e3\nb = .5\nc = -0\nd = nan\ne = inf\nf = 1e999\ng = 0x10\nh = 99999999999\n");
    CHECK(spec.getNumber("a") == 1000.0);
    CHECK(spec.getNumber("b") == 0.5);
    CHECK(spec.getNumber("c") == 0.0);
    for (const char* key : {"d", "e", "f", "g"}) {
        INFO(key);
        CHECK(inputErrorFrom([&] { spec.getNumber(key); }));
    }
    CHECK(inputErrorFrom([&] { spec.getInt("h"); }));  // does not fit an int
}

TEST_CASE("CaseSpec::requireAllKeysUsed: names the first key nobody read", "[lab][manifest]") {
    const CaseSpec spec = caseWith("camera = orbit\n"   // line 3
                                   "distnace = 6\n"     // line 4
                                   "resolutoin = 64 64\n"  // line 5
                                   "wireframe = yes\n"); // line 6
    CHECK(spec.getString("camera") == "orbit");
    CHECK(spec.getNumber("distance", 5.0) == 5.0);  // the lab asks for 'distance' and gets the fallback
    CHECK(spec.has("wireframe"));                  // asking counts as reading

    const auto error = inputErrorFrom([&] { spec.requireAllKeysUsed(); });
    REQUIRE(error);
    CHECK(error->file() == "cases.ini");
    CHECK(error->line() == 4);
    CHECK(error->message() == "unknown key 'distnace' in case 'test' (did you mean 'distance'?)");

    spec.getNumber("distnace");  // once read, the next unread key is reported
    const auto next = inputErrorFrom([&] { spec.requireAllKeysUsed(); });
    REQUIRE(next);
    CHECK(next->line() == 5);
    CHECK(next->message() == "unknown key 'resolutoin' in case 'test' (did you mean 'resolution'?)");

    const CaseSpec unrelated = caseWith("zzz = 1\n");
    const auto plain = inputErrorFrom([&] { unrelated.requireAllKeysUsed(); });
    REQUIRE(plain);
    CHECK(plain->message() == "unknown key 'zzz' in case 'test'");

    const CaseSpec none = caseWith("points = 3\n");
    CHECK_NOTHROW(none.requireAllKeysUsed());
}

TEST_CASE("LabManifest: find() and caseNames()", "[lab][manifest]") {
    const LabManifest manifest = parseManifest("lab = x\n[case one]\n[case two]\n[case three]\n", "cases.ini");
    CHECK(manifest.caseNames() == "one, two, three");
    REQUIRE(manifest.find("two") != nullptr);
    CHECK(manifest.find("two")->line == 3);
    CHECK(manifest.find("TWO") == nullptr);
    CHECK(LabManifest().caseNames().empty());
}

TEST_CASE("parseManifest: a property check is a case with a check key and no picture", "[lab][manifest]") {
    const LabManifest manifest = parseManifest("lab = 05_test\n"
                                               "[case sun]\n"
                                               "resolution = 64 32\n"
                                               "[case texel_snapping]\n"
                                               "description = A property check\n"
                                               "check = texel_snapping\n"
                                               "points = 1\n"
                                               "[case moon]\n",
                                               "cases.ini");
    REQUIRE(manifest.cases.size() == 3);
    CHECK(manifest.cases[0].check.empty());
    CHECK(manifest.cases[1].check == "texel_snapping");
    CHECK(manifest.cases[1].points == 1.0);
    // The check key is the parser's, not a scene parameter the lab must read.
    CHECK_NOTHROW(manifest.cases[1].requireAllKeysUsed());
    const std::vector<const CaseSpec*> pictures = manifest.pictureCases();
    REQUIRE(pictures.size() == 2);
    CHECK(pictures[0]->name == "sun");
    CHECK(pictures[1]->name == "moon");

    const auto bad = parseError(kHead + "check = texel snapping\n");
    REQUIRE(bad);
    CHECK(bad->line() == 4);
    CHECK(contains(bad->message(), "expected 'check = NAME' with letters, digits and '_', got 'texel snapping'"));
    // A misspelt key close to a typed one is suggested ("did you mean"), max_flip_mean and check included.
    const LabManifest typo = parseManifest("lab = 05_test\n[case a]\nmax_flip_maen = 0.1\n", "cases.ini");
    const auto unused = inputErrorFrom([&] { typo.cases[0].requireAllKeysUsed(); });
    REQUIRE(unused);
    CHECK(contains(unused->message(), "max_flip_mean"));
}

TEST_CASE("CaseManifest: one table of typed keys drives parsing, errors and suggestions, and the guide lists it") {
    // Every key of the table stores a good value and names what it expected for a bad one.
    const char* const good[][2] = {{"description", "A view"}, {"resolution", "64 32"}, {"points", "2"},
                                   {"visibility", "hidden"},  {"tolerance", "8"},       {"max_bad_fraction", "0.01"},
                                   {"max_flip_mean", "0.1"},  {"check", "camera_limits"}};
    REQUIRE(caseKeys().size() == std::size(good));
    for (const auto& [key, value] : good) {
        INFO(key);
        const CaseKey* typed = findCaseKey(key);
        REQUIRE(typed);
        CHECK_NOTHROW(parseManifest(std::string("lab = 05_test\n[case a]\n") + key + " = " + value + "\n", "c.ini"));
        if (std::string(key) == "description") continue;   // any text is a description
        const auto bad = parseError(kHead + key + " = nonsense!\n");
        REQUIRE(bad);
        CHECK(bad->line() == 4);
        CHECK(contains(bad->message(), "expected " + std::string(typed->expected) + ", got 'nonsense!'"));
        // Outside a case, a typed key is named as misplaced, not as unknown.
        const auto misplaced = parseError(std::string(key) + " = " + value + "\nlab = 05_test\n[case a]\n");
        REQUIRE(misplaced);
        CHECK(contains(misplaced->message(), "outside any [case NAME] section"));
    }
    CHECK_FALSE(findCaseKey("camera"));   // a scene parameter, the lab's

    // The instructor guide's table of "keys the grader reads itself" is this table, in order.
    std::ifstream guide(stoa::paths::sourceDir() / "docs" / "instructor-guide.md");
    REQUIRE(guide);
    std::string line;
    while (std::getline(guide, line) && line.find("Keys the grader reads itself") == std::string::npos) {}
    std::vector<std::string> documented;
    bool inTable = false;
    while (std::getline(guide, line)) {
        if (line.rfind("| `", 0) == 0) {
            inTable = true;
            documented.push_back(line.substr(3, line.find('`', 3) - 3));
        } else if (inTable) {
            break;
        }
    }
    std::vector<std::string> table;
    for (const CaseKey& typed : caseKeys()) table.emplace_back(typed.key);
    CHECK(documented == table);
}
