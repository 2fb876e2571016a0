// The batch grader's logic without building anything: reading results.json,
// finding a submission's labs/ tree, student names, the gradebook, and the
// determinism check's exact image comparison.

#include "BatchGradeJson.hpp"
#include "BatchGradeSubmissions.hpp"
#include "ClassGrader.hpp"
#include "CommandLine.hpp"
#include "DeterminismCheck.hpp"

#include <stoa/core/InputError.hpp>

#include "TempFolder.hpp"
#include "catch.hpp"

using namespace stoa;
using namespace stoa::grader;

TEST_CASE("parseJson reads what JsonWriter writes, and dump() writes it back") {
    std::string text = R"({"score": 7.5, "tests": [{"name": "01_a/x", "ok": true, "tags": ["01_a", "failed"],
                          "output": "line\nnext \"q\" \u00e9"}], "none": null})";
    JsonValue document = parseJson(text);
    REQUIRE(document.isObject());
    CHECK(document.find("score")->asNumber() == 7.5);
    const JsonValue& test = document.find("tests")->items().at(0);
    CHECK(test.find("name")->asString() == "01_a/x");
    CHECK(test.find("ok")->asBoolean());
    CHECK(test.find("output")->asString() == "line\nnext \"q\" \xC3\xA9");
    CHECK(test.find("tags")->items().size() == 2);
    CHECK(document.find("none")->type() == JsonValue::Type::Null);
    CHECK(document.find("missing") == nullptr);

    JsonValue again = parseJson(document.dump());
    CHECK(again.find("tests")->items().at(0).find("output")->asString() == test.find("output")->asString());
    CHECK(again.members().size() == document.members().size());
}

TEST_CASE("parseJson names the file and line of bad JSON") {
    try {
        parseJson("{\n  \"a\": 1,\n  \"b\" 2\n}", "results.json");
        FAIL("no error");
    } catch (const InputError& error) {
        CHECK(error.file() == "results.json");
        CHECK(error.line() == 3);
        CHECK(std::string(error.what()).find("':'") != std::string::npos);
    }
    CHECK_THROWS_AS(parseJson("[1, 2"), InputError);
    CHECK_THROWS_AS(parseJson("{} extra"), InputError);
}

TEST_CASE("studentName drops the archive extension and odd characters") {
    CHECK(studentName("subs/alice") == "alice");
    CHECK(studentName("subs/bob.zip") == "bob");
    CHECK(studentName("subs/carol.tar.gz") == "carol");
    CHECK(studentName("subs/Dan Smith.TGZ") == "Dan_Smith");
}

TEST_CASE("findLabsFolder finds labs/ at the top, one folder down, or the lab folders themselves") {
    test::TempFolder folder("batch-labs");
    folder.write("top/labs/01_transforms/student/transforms.cpp", "");
    CHECK(findLabsFolder(folder / "top") == folder / "top" / "labs");

    folder.write("nested/alice-main/labs/01_transforms/student/transforms.cpp", "");
    folder.write("nested/__MACOSX/junk", "");
    folder.write("nested/.hidden", "");
    CHECK(findLabsFolder(folder / "nested") == folder / "nested" / "alice-main" / "labs");

    folder.write("bare/01_transforms/student/transforms.cpp", "");
    CHECK(findLabsFolder(folder / "bare") == folder / "bare");

    folder.write("empty/readme.txt", "");
    CHECK_THROWS_AS(findLabsFolder(folder / "empty"), InputError);
}

TEST_CASE("findSubmissions takes folders and archives, skips the rest, refuses two of one student") {
    test::TempFolder folder("batch-find");
    folder.write("subs/alice/labs/x", "");
    folder.write("subs/bob.zip", "");
    folder.write("subs/carol.tar.gz", "");
    folder.write("subs/notes.txt", "");
    folder.write("subs/.DS_Store", "");
    std::vector<std::string> skipped;
    std::vector<Submission> submissions = findSubmissions(folder / "subs", skipped);
    REQUIRE(submissions.size() == 3);
    CHECK(submissions[0].student == "alice");
    CHECK(submissions[0].kind == SubmissionKind::Folder);
    CHECK(submissions[1].kind == SubmissionKind::Zip);
    CHECK(submissions[2].kind == SubmissionKind::TarGz);
    REQUIRE(skipped.size() == 1);
    CHECK(skipped[0].find("notes.txt") != std::string::npos);

    folder.write("subs/alice.zip", "");
    CHECK_THROWS_AS(findSubmissions(folder / "subs", skipped), InputError);
}

TEST_CASE("A staged submission is a copy: links stay links, and a changed input is named") {
    test::TempFolder folder("batch-stage");
    folder.write("subs/alice/labs/01_transforms/student/transforms.cpp", "int a;\n");
    folder.write("subs/alice/labs/01_transforms/student/cameras.cpp", "int b;\n");
    folder.write("elsewhere/secret.cpp", "int secret;\n");
    std::filesystem::create_symlink(folder / "elsewhere/secret.cpp", folder / "subs/alice/labs/link.cpp");
    Submission alice{"alice", folder / "subs/alice", SubmissionKind::Folder};

    std::vector<InputFile> before = recordInputs(alice);
    REQUIRE(before.size() == 3);
    CHECK(before[0].path == "labs/01_transforms/student/cameras.cpp");
    std::filesystem::path labs = stageSubmission(alice, folder / "stage");
    CHECK(labs == folder / "stage" / "labs");
    CHECK(std::filesystem::is_regular_file(labs / "01_transforms/student/transforms.cpp"));
    CHECK(std::filesystem::is_symlink(labs / "link.cpp"));   // a link, never followed by the grader
    CHECK(changedInputs(before, recordInputs(alice)).empty());

    folder.write("subs/alice/labs/01_transforms/student/transforms.cpp", "#error sabotaged\n");
    folder.write("subs/alice/labs/new.cpp", "");
    std::filesystem::remove(folder / "subs/alice/labs/01_transforms/student/cameras.cpp");
    CHECK(changedInputs(before, recordInputs(alice)) ==
          std::vector<std::string>{"labs/01_transforms/student/transforms.cpp", "labs/new.cpp (new)",
                                   "labs/01_transforms/student/cameras.cpp (gone)"});
    CHECK(inputsText(before).find("  labs/01_transforms/student/transforms.cpp\n") != std::string::npos);
}

TEST_CASE("addResults sums points per lab from results.json and names what did not pass") {
    test::TempFolder folder("batch-results");
    std::filesystem::path file = folder.write("results.json", R"({"score": 3, "tests": [
        {"name": "01_a/one", "score": 2, "max_score": 2, "status": "passed", "tags": ["01_a", "passed"]},
        {"name": "01_a/two", "score": 0, "max_score": 3, "status": "failed", "tags": ["01_a", "failed"]},
        {"name": "02_b/one", "score": 0, "max_score": 4, "status": "failed", "tags": ["02_b", "not attempted"]}]})");
    StudentGrade grade;
    grade.labs["01_a"];
    grade.labs["02_b"];
    addResults(file, grade);
    CHECK(grade.labs["01_a"].points == 2);
    CHECK(grade.labs["01_a"].maxPoints == 5);
    CHECK(grade.labs["01_a"].note == "1 failed");
    CHECK(grade.labs["02_b"].maxPoints == 4);
    CHECK(grade.labs["02_b"].note == "not attempted");
}

TEST_CASE("addBuildFailures counts a lab that did not compile in the score and in the output's total") {
    test::TempFolder folder("batch-build-failures");
    std::filesystem::path file = folder.write("results.json", R"({"score": 4, "output": "score: 4 / 4 (2 passed)\n",
        "tests": [
        {"name": "01_a/one", "score": 2, "max_score": 2, "status": "passed", "tags": ["01_a", "passed"]},
        {"name": "01_a/two", "score": 2, "max_score": 2, "status": "passed", "tags": ["01_a", "passed"]}]})");
    StudentGrade grade;
    grade.labs["01_a"].maxPoints = 4;
    grade.labs["02_b"].maxPoints = 10;
    addBuildFailures(file, grade, {{"02_b", "b.cpp:7:10: fatal error: b.hpp: No such file or directory"}});

    JsonValue document = readJsonFile(file);
    CHECK(document.find("score")->asNumber() == 4);
    const std::string output = document.find("output")->asString();
    CHECK(output.rfind("score: 4 / 14 (2 passed, 1 lab does not compile)\n", 0) == 0);
    CHECK(output.find("4 / 4") == std::string::npos);
    CHECK(output.find("lab 02_b does not compile (see its test)") != std::string::npos);
    const JsonValue& build = document.find("tests")->items().back();
    CHECK(build.find("name")->asString() == "02_b/build");
    CHECK(build.find("max_score")->asNumber() == 10);
    CHECK(build.find("output")->asString().find("fatal error: b.hpp") != std::string::npos);
}

TEST_CASE("addBuildFailures writes a score line when no lab compiled, and none for a lab its cascade graded") {
    test::TempFolder folder("batch-build-failures");
    std::filesystem::path file = folder / "results.json";   // nothing graded: no results.json yet
    StudentGrade grade;
    grade.labs["01_a"].maxPoints = 4;
    grade.labs["02_b"].maxPoints = 6;
    addBuildFailures(file, grade, {{"01_a", "error one"}, {"02_b", "error two"}});
    JsonValue document = readJsonFile(file);
    CHECK(document.find("score")->asNumber() == 0);
    CHECK(document.find("output")->asString().rfind("score: 0 / 10 (2 labs do not compile)\n", 0) == 0);

    // 02_b's cascade program built and was graded: its build test is worth 0 and
    // its cases already stand in the counts.
    std::filesystem::path graded = folder.write("graded.json", R"({"score": 6,
        "output": "score: 6 / 6 (3 passed)\nlab 01_a: nothing attempted yet\n", "tests": [
        {"name": "02_b/one", "score": 6, "max_score": 6, "status": "passed", "tags": ["02_b", "passed", "cascade"]}]})");
    grade.labs["02_b"].cascadeBuilt = true;
    addBuildFailures(graded, grade, {{"02_b", "error two"}});
    const std::string output = readJsonFile(graded).find("output")->asString();
    CHECK(output == "score: 6 / 6 (3 passed)\nlab 01_a: nothing attempted yet\nlab 02_b does not compile (see its test)\n");
}

TEST_CASE("gradebookCsv writes one row per student and quotes notes with commas") {
    StudentGrade alice;
    alice.student = "alice";
    alice.labs["01_a"].points = 2.5;
    alice.points = 2.5;
    alice.maxPoints = 5;
    alice.status = "graded";
    alice.notes = {"01_a: 1 failed, 1 error", "say \"hi\""};
    std::string csv = gradebookCsv({"01_a"}, {alice});
    CHECK(csv == "student,01_a,total,max,status,notes\n"
                 "alice,2.5,2.5,5,graded,\"01_a: 1 failed, 1 error; say \"\"hi\"\"\"\n");
}

TEST_CASE("compareExactly counts differing pixels and the largest difference") {
    Image a(4, 3, 4);
    Image b(4, 3, 4);
    CHECK(compareExactly(a, b).identical());
    CHECK(compareExactly(a, b).describe() == "identical");
    b.data()[0] = 2;                 // pixel (0,0), red
    b.data()[4 * 5 + 2] = 1;         // pixel (1,1), blue
    ImageDifference difference = compareExactly(a, b);
    CHECK(difference.differingPixels == 2);
    CHECK(difference.maxChannelDifference == 2);
    CHECK(difference.describe() == "2 pixels differ, by at most 2 levels");
    CHECK_FALSE(compareExactly(a, Image(3, 4, 4)).sameSize);
    CHECK(determinismVariants(4).size() == 4);
    CHECK(determinismVariants(4).back().environment == std::vector<std::string>{"LP_NUM_THREADS=2"});
    CHECK(determinismVariants(0).size() == 4);
    // Two threads are llvmpipe's default on a 2-core machine: LP_NUM_THREADS=2 would repeat runs 1 and 2.
    REQUIRE(determinismVariants(2).size() == 3);
    CHECK(determinismVariants(2)[2].environment == std::vector<std::string>{"LP_NUM_THREADS=1"});
}

TEST_CASE("The determinism check (--determinism) is its own mode and combines with --lab and --case only") {
    Options options = parseCommandLine({"--determinism", "--lab", "01", "--case", "orbit_front", "--jobs", "2"});
    CHECK(options.mode == Mode::Determinism);
    CHECK(options.labs == std::vector<std::string>{"01"});
    CHECK_THROWS_AS(parseCommandLine({"--determinism", "--check-mistakes"}), UsageError);
    CHECK_THROWS_AS(parseCommandLine({"--determinism", "--update-references"}), UsageError);
    CHECK_THROWS_AS(parseCommandLine({"--determinism", "--json", "r.json"}), UsageError);
    CHECK_THROWS_AS(parseCommandLine({"--determinism=yes"}), UsageError);
}
