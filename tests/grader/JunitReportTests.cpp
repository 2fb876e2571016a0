// JUnit XML.

#include "catch.hpp"

#include "JunitReport.hpp"

using namespace stoa::grader;

namespace {

GradeResult result(const std::string& lab, const std::string& name, GradeStatus status, double seconds,
                   const std::string& reason = "") {
    GradeResult r;
    r.lab = lab;
    r.caseName = name;
    r.status = status;
    r.seconds = seconds;
    r.reason = reason;
    return r;
}

} // namespace

TEST_CASE("junitXml: a suite per lab, a testcase per case, statuses as JUnit elements", "[grader][report][junit]") {
    std::vector<GradeResult> results = {
        result("01_transforms", "orbit_front", GradeStatus::Passed, 0.5),
        result("01_transforms", "wide_lens", GradeStatus::Failed, 0.25, "4.2% pixels off (max 255) <&\"'>"),
        result("02_shading", "sun", GradeStatus::NotAttempted, 0.125, "not implemented: shade()"),
        result("02_shading", "point_lights", GradeStatus::Error, 1.0, "crashed with SIGSEGV"),
        result("02_shading", "everything", GradeStatus::NoReference, 0.0, "no reference image"),
    };
    results[1].hint = "The aspect ratio is upside down.";
    results[1].hintDocs = "docs/labs/01_transforms.md#the-projection-matrix";
    results[1].hintMistake = "aspect_inverted";
    results[3].programOutput = std::string("Segmentation fault\x01\xFF");
    std::string xml = junitXml(results);

    CHECK(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"stoa-grade\" tests=\"5\" "
                    "failures=\"1\" errors=\"2\" skipped=\"1\" time=\"1.875\">",
                    0) == 0);
    CHECK(xml.find("<testsuite name=\"01_transforms\" tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"0\" "
                   "time=\"0.750\">") != std::string::npos);
    CHECK(xml.find("<testsuite name=\"02_shading\" tests=\"3\" failures=\"0\" errors=\"2\" skipped=\"1\"") !=
          std::string::npos);
    CHECK(xml.find("<testcase name=\"orbit_front\" classname=\"01_transforms\" time=\"0.500\"/>") !=
          std::string::npos);
    CHECK(xml.find("<failure message=\"4.2% pixels off (max 255) &lt;&amp;&quot;&apos;&gt;\" "
                   "type=\"image mismatch\">") != std::string::npos);
    CHECK(xml.find("known mistake aspect_inverted): The aspect ratio is upside down.") != std::string::npos);
    CHECK(xml.find("read: docs/labs/01_transforms.md#the-projection-matrix") != std::string::npos);
    CHECK(xml.find("<skipped message=\"not attempted\">not implemented: shade()</skipped>") != std::string::npos);
    CHECK(xml.find("<error message=\"crashed with SIGSEGV\" type=\"error\">") != std::string::npos);
    CHECK(xml.find("<error message=\"no reference image\" type=\"no reference\">") != std::string::npos);
    CHECK(xml.find("<system-out>Segmentation fault\xEF\xBF\xBD\xEF\xBF\xBD</system-out>") != std::string::npos);
    CHECK(xml.find('\x01') == std::string::npos);
    CHECK(xml.substr(xml.size() - 14) == "</testsuites>\n");
    // Every element opened is closed: as many testcases as results.
    std::size_t testcases = 0;
    for (std::size_t at = xml.find("<testcase "); at != std::string::npos; at = xml.find("<testcase ", at + 1))
        ++testcases;
    CHECK(testcases == results.size());
    std::size_t closed = 0;
    for (std::size_t at = xml.find("</testcase>"); at != std::string::npos; at = xml.find("</testcase>", at + 1))
        ++closed;
    CHECK(closed == results.size() - 1);   // the passed case closes itself

    CHECK(junitXml({}) == "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"stoa-grade\" tests=\"0\" "
                          "failures=\"0\" errors=\"0\" skipped=\"0\" time=\"0.000\">\n</testsuites>\n");
}
