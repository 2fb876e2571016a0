// The class report and the similarity ranking without grading anything:
// results.json read into a student's record, the class summed up, the page
// escaped, --report-from's folder, given code told apart from a student's own,
// and SIM's output read back.

#include "ClassReport.hpp"
#include "Similarity.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>

#include "TempFolder.hpp"
#include "catch.hpp"

#include <algorithm>

using namespace stoa;
using namespace stoa::grader;

namespace {

// A results.json as stoa-grade-class writes it: lab 01 with a hint and a
// timeout, lab 02 graded through its cascade (its own run not counted), lab 03
// that did not compile.
const char* const kResults = R"({"score": 5, "output": "score: 5 / 12", "tests": [
  {"name": "01_a/front", "score": 2, "max_score": 2, "status": "passed", "tags": ["01_a", "passed"]},
  {"name": "01_a/side", "score": 0, "max_score": 2, "status": "failed", "tags": ["01_a", "failed"],
   "output": "failed: 3% of pixels\n\nHint (a suggestion, not a verdict): this image looks like the known mistake 'no_translation': The eye is not moved.\n",
   "extra_data": {"hint_mistake": "no_translation", "hint_docs": "docs/labs/01_a.md#view"}},
  {"name": "01_a/walk", "score": 0, "max_score": 1, "status": "failed", "tags": ["01_a", "error"],
   "output": "error: timed out after 15 s without computing (0.0 s of processor time)\n"},
  {"name": "02_b/sun", "score": 0, "max_score": 0, "status": "failed", "tags": ["02_b", "failed", "not counted"]},
  {"name": "02_b/sun [cascade]", "score": 3, "max_score": 3, "status": "passed", "tags": ["02_b", "passed", "cascade"]},
  {"name": "03_c/build", "score": 0, "max_score": 4, "status": "failed", "tags": ["03_c"],
   "output": "The lab does not compile:\n03_c/student/normals.cpp:3:1: error: 'x' does not name a type\n  x y;\n"}]})";

StudentRecord student(const std::string& name, double points01, const std::string& status01,
                      const std::string& mistake = "") {
    StudentRecord record;
    record.student = name;
    record.status = "graded";
    LabRecord& lab = record.labs["01_a"];
    lab.points = points01;
    lab.maxPoints = 4;
    lab.cases.push_back({"front", status01, false, mistake, mistake.empty() ? "" : "the hint", ""});
    lab.cases.push_back({"check_bound", points01 >= 2 ? "passed" : "failed", false, "", "", ""});
    record.points = points01;
    record.maxPoints = 4;
    record.reportLink = name + "/report.html";
    return record;
}

LabCases labA() {
    LabCases lab;
    lab.lab = "01_a";
    lab.maxPoints = 4;
    lab.order = {"front", "check_bound", "hidden_side"};   // no student has hidden_side: it is left out
    lab.descriptions["front"] = "The view from the front";
    lab.checks.insert("check_bound");
    return lab;
}

} // namespace

TEST_CASE("readStudentResults reads the counted cases, hints, timeouts and compile errors of each lab") {
    test::TempFolder folder("class-results");
    StudentRecord record = readStudentResults(folder.write("results.json", kResults), "alice");
    CHECK(record.student == "alice");
    CHECK(record.points == 5);
    CHECK(record.maxPoints == 12);
    REQUIRE(record.labs.size() == 3);
    const LabRecord& a = record.labs.at("01_a");
    CHECK(a.points == 2);
    CHECK(a.maxPoints == 5);
    REQUIRE(a.cases.size() == 3);
    CHECK(a.cases[1].hintMistake == "no_translation");
    CHECK(a.cases[1].hint == "The eye is not moved.");
    CHECK(a.cases[1].hintDocs == "docs/labs/01_a.md#view");
    CHECK(a.timedOutCases() == std::vector<std::string>{"walk"});
    const LabRecord& b = record.labs.at("02_b");
    REQUIRE(b.cases.size() == 1);   // the run that does not count is left out
    CHECK(b.cases[0].name == "sun");
    CHECK(b.cases[0].status == "passed");
    const LabRecord& c = record.labs.at("03_c");
    CHECK(c.doesNotCompile);
    CHECK(c.compileError == "03_c/student/normals.cpp:3:1: error: 'x' does not name a type");
    CHECK(c.cases.empty());
}

TEST_CASE("readStudentResults names the file of a malformed results.json") {
    test::TempFolder folder("class-bad-results");
    for (const char* text : {"{\"tests\": [", "[1, 2]", "{\"tests\": {}}", "{\"tests\": [3]}", "{}"}) {
        std::filesystem::path file = folder.write("results.json", text);
        try {
            readStudentResults(file, "bob");
            FAIL("no error for " << text);
        } catch (const InputError& error) {
            CHECK(error.file() == file.string());
        }
    }
    // Gradescope's fallback for a submission that could not be graded: no tests, an output.
    StudentRecord record = readStudentResults(
        folder.write("results.json", R"({"score": 0, "output": "Your submission could not be graded.\nmore"})"), "bob");
    CHECK(record.labs.empty());
    CHECK(record.status == "not graded");
    CHECK(record.note == "Your submission could not be graded.");
}

TEST_CASE("distributionOf puts scores in tenths of the maximum and full marks on their own") {
    ScoreDistribution scores = distributionOf({0, 1.9, 2, 9.99, 10, 10, 5}, 10);
    CHECK(scores.bins[0] == 1);
    CHECK(scores.bins[1] == 1);
    CHECK(scores.bins[2] == 1);
    CHECK(scores.bins[5] == 1);
    CHECK(scores.bins[9] == 1);
    CHECK(scores.bins[10] == 2);
    CHECK(scores.median == 5);
    CHECK(scores.mean == Approx((0 + 1.9 + 2 + 9.99 + 10 + 10 + 5) / 7));
    CHECK(distributionOf({1, 3}, 4).median == 2);
    CHECK(distributionOf({}, 4).mean == 0);
    CHECK(distributionOf({0}, 0).bins[0] == 1);
}

TEST_CASE("summarizeClass counts each case, names the mistakes' students, and ranks what to teach again") {
    std::vector<StudentRecord> students = {student("ann", 4, "passed"), student("ben", 0, "failed", "no_translation"),
                                           student("cat", 0, "failed", "no_translation"),
                                           student("dan", 0, "not attempted"), student("fay", 0, "failed")};
    students[3].labs["01_a"].cases = {{"front", "not attempted", false, "", "", ""}};
    StudentRecord eve;
    eve.student = "eve";
    eve.status = "no labs/ folder";
    eve.note = "no labs/ in the archive";
    students.push_back(eve);
    ClassSummary summary = summarizeClass(students, {labA()}, "test");
    REQUIRE(summary.labs.size() == 1);
    const LabSummary& lab = summary.labs[0];
    CHECK(lab.scores.maxPoints == 4);
    CHECK(lab.scores.bins[10] == 1);
    CHECK(lab.scores.bins[0] == 5);
    REQUIRE(lab.cases.size() == 2);
    const CaseSummary& front = lab.cases[0].name == "front" ? lab.cases[0] : lab.cases[1];
    CHECK(front.passed == 1);
    CHECK(front.failed == 3);
    CHECK(front.notAttempted == 1);
    CHECK(front.missing == 1);
    CHECK(front.description == "The view from the front");
    const CaseSummary& check = lab.cases[0].name == "check_bound" ? lab.cases[0] : lab.cases[1];
    CHECK(check.propertyCheck);
    REQUIRE(lab.mistakes.size() == 1);
    CHECK(lab.mistakes[0].students == std::vector<std::string>{"ben", "cat"});
    CHECK(lab.notAttempted == std::vector<std::string>{"dan"});
    REQUIRE(summary.notGraded.size() == 1);
    CHECK(summary.notGraded[0].student == "eve");
    // Most students first; a case counts only the students no hint explained.
    REQUIRE(summary.teachAgain.size() == 3);
    CHECK(summary.teachAgain[0].kind == "check");
    CHECK(summary.teachAgain[0].students == std::vector<std::string>{"ben", "cat", "fay"});
    CHECK(summary.teachAgain[1].kind == "mistake");
    CHECK(summary.teachAgain[1].students == std::vector<std::string>{"ben", "cat"});
    CHECK(summary.teachAgain[2].kind == "case");
    CHECK(summary.teachAgain[2].students == std::vector<std::string>{"fay"});
    CHECK(summary.overall.maxPoints == 4);

    std::string json = classJson(summary);
    CHECK(json.find("\"teach_again\"") != std::string::npos);
    CHECK(json.find("\"no_translation\"") != std::string::npos);
}

TEST_CASE("class.html draws its histograms itself and escapes what students control") {
    std::vector<StudentRecord> students = {student("<script>alert(1)</script>", 0, "failed", "m\"<b>"),
                                           student("ok", 4, "passed")};
    students[0].labs["01_a"].doesNotCompile = true;
    students[0].labs["01_a"].compileError = "a.cpp:1: error: <img src=x onerror=alert(2)>";
    ClassSummary summary = summarizeClass(students, {labA()}, "<from>");
    std::string html = classHtml(summary);
    CHECK(html.find("<svg") != std::string::npos);
    CHECK(html.find("class=\"bar\"") != std::string::npos);
    CHECK(html.find("<script") == std::string::npos);
    CHECK(html.find("<img") == std::string::npos);
    CHECK(html.find("&lt;script&gt;") != std::string::npos);
    CHECK(html.find("m&quot;&lt;b&gt;") != std::string::npos);
    CHECK(html.find("&lt;from&gt;") != std::string::npos);
    // The link to the student's report is a relative path, percent-encoded.
    CHECK(html.find("href=\"%3Cscript%3Ealert%281%29%3C/script%3E/report.html\"") != std::string::npos);
    CHECK(html.find("http") == html.find("http://www.w3.org/2000/svg"));   // nothing loaded from elsewhere
}

TEST_CASE("readResultsFolder takes STUDENT/results.json and STUDENT.json, and names what it cannot read") {
    test::TempFolder folder("class-report-from");
    std::vector<std::string> unreadable;
    CHECK_THROWS_AS(readResultsFolder(folder / "missing", unreadable), InputError);
    CHECK_THROWS_WITH(readResultsFolder(folder.path(), unreadable), Catch::Contains("no results here"));
    folder.write("alice/results.json", kResults);
    folder.write("alice/report.html", "<html></html>");
    folder.write("bob.json", kResults);
    folder.write("carol/results.json", "{\"tests\": [");
    folder.write("class.json", "{}");   // an earlier report, not a student
    folder.write("dan/submission-files.txt", "");   // stoa-grade-class graded nothing of dan's
    folder.write("notes/readme.txt", "");           // another folder: not a student
    std::vector<StudentRecord> records = readResultsFolder(folder.path(), unreadable);
    REQUIRE(records.size() == 2);
    CHECK(records[0].student == "alice");
    CHECK(records[0].reportLink == "alice/report.html");
    CHECK(records[1].student == "bob");
    CHECK(records[1].reportLink.empty());
    REQUIRE(unreadable.size() == 2);
    auto names = [&](const std::string& text) {
        return std::any_of(unreadable.begin(), unreadable.end(),
                           [&](const std::string& why) { return why.find(text) != std::string::npos; });
    };
    CHECK(names("carol/results.json:"));
    CHECK(names("dan/results.json: none"));
}

TEST_CASE("givenLines marks the stub's lines in the student's file, in order, whatever the spacing") {
    std::vector<std::string> stub = {"#include \"lab.hpp\"", "", "int f(int x) {", "    // TODO", "    (void)x;",
                                     "    throw NotImplemented(\"f\");", "}"};
    std::vector<std::string> mine = {"#include \"lab.hpp\"", "", "int  f(int x)  {", "    return x * 2;", "}", "",
                                     "int helper() { return 1; }"};
    std::vector<bool> given = givenLines(stub, mine);
    CHECK(given == std::vector<bool>{true, false, true, false, true, false, false});
    CHECK(givenLines({}, mine) == std::vector<bool>(mine.size(), false));
    // Another brace style and spacing: the signature and its brace are still given.
    std::vector<std::string> allman = {"int f( int x )", "{", "\treturn x * 2;", "}"};
    CHECK(givenLines(stub, allman) == std::vector<bool>{true, true, false, true});
}

TEST_CASE("SIM's output is read back: token counts, percentages, runs from either side") {
    std::string percentages = "File s0001.txt: 671 tokens, 71 lines\nFile s0002.txt: 90 tokens, 20 lines\n"
                              "Total input: 2 files (2 new, 0 old), 761 tokens\n\n"
                              "s0001.txt consists for 12 % of s0002.txt material\n"
                              "s0002.txt consists for 88 % of s0001.txt material\n";
    CHECK(parseTokenCounts(percentages) == std::map<std::string, int>{{"s0001.txt", 671}, {"s0002.txt", 90}});
    CHECK(parseTokenCounts("File s0003.txt: 25 words, 2 lines\n") == std::map<std::string, int>{{"s0003.txt", 25}});
    auto parsed = parsePercentages(percentages);
    CHECK(parsed.at({"s0001.txt", "s0002.txt"}) == 12);
    CHECK(parsed.at({"s0002.txt", "s0001.txt"}) == 88);
    std::string runs = "File s0001.txt: 671 tokens, 71 lines\n\n"
                       "s0002.txt: line 3-9                      |s0001.txt: line 40-47                 [60]\n"
                       "s0001.txt: line 14-30                    |s0002.txt: line 12-20                 [120]\n";
    std::vector<SharedRun> shared = parseRuns(runs, "s0001.txt", "s0002.txt");
    REQUIRE(shared.size() == 2);
    CHECK(shared[0].firstA == 14);
    CHECK(shared[0].lastB == 20);
    CHECK(shared[0].tokens == 120);
    CHECK(shared[1].firstA == 40);
    CHECK(shared[1].firstB == 3);
}

TEST_CASE("The student files of a lab come from its stoa_add_lab(), and pick the SIM that reads them") {
    std::vector<std::string> files = studentFilesOf(paths::sourceDir(), "01_transforms");
    CHECK(files == std::vector<std::string>{"transforms.cpp", "cameras.cpp"});
    CHECK_THROWS_AS(studentFilesOf(paths::sourceDir(), "99_missing"), InputError);
    CHECK(simToolFor({"a.cpp", "b.glsl"}) == "sim_c");
    CHECK(simToolFor({"a.cpp", "agents.xml"}) == "sim_text");
}
