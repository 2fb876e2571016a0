// The self-contained HTML report.

#include "catch.hpp"

#include "HtmlReport.hpp"

#include "TempFolder.hpp"

#include <fstream>

using namespace stoa::grader;

namespace {

GradeResult result(const std::string& name, GradeStatus status, double points, double maxPoints,
                   const std::string& reason) {
    GradeResult r;
    r.lab = "02_shading";
    r.caseName = name;
    r.status = status;
    r.points = points;
    r.maxPoints = maxPoints;
    r.reason = reason;
    return r;
}

std::size_t find(const std::string& text, const std::string& what) { return text.find(what); }

} // namespace

TEST_CASE("failuresFirst orders failed, error, no reference, not attempted, passed", "[grader][report][html]") {
    std::vector<GradeResult> results = {result("a", GradeStatus::Passed, 1, 1, ""),
                                        result("b", GradeStatus::NotAttempted, 0, 1, ""),
                                        result("c", GradeStatus::Failed, 0, 1, ""),
                                        result("d", GradeStatus::Error, 0, 1, ""),
                                        result("e", GradeStatus::Failed, 0, 1, ""),
                                        result("f", GradeStatus::NoReference, 0, 1, "")};
    CHECK(failuresFirst(results) == std::vector<std::size_t>{2, 4, 3, 5, 1, 0});
    CHECK(failuresFirst({}).empty());
}

TEST_CASE("htmlReport: totals first, failures first, images embedded, hint linked, text escaped",
          "[grader][report][html]") {
    stoa::test::TempFolder folder("html");
    std::vector<GradeResult> results = {
        result("sun", GradeStatus::Passed, 5, 5, "0.00% pixels off"),
        result("highlights", GradeStatus::Failed, 0, 5, "3.2% pixels off <max 200> & \"more\""),
        result("secret", GradeStatus::Failed, 0, 2, "hidden one"),
        result("crash", GradeStatus::Error, 0, 1, "crashed with SIGSEGV"),
    };
    results[1].renderedImage = folder.write("yours.png", "YOURS");
    results[1].referenceImage = folder.write("reference.png", "REF");
    results[1].heatMapImage = folder.write("heat.png", "HEAT");
    results[1].metrics = CompareMetrics{0.032, 4.1, 200, 0.0421};
    results[1].hint = "Use H = normalize(L + V) <not R>.";
    results[1].hintDocs = "docs/labs/02_shading.md#the-half-vector";
    results[1].hintMistake = "no_half_vector";
    results[1].hintImage = folder.write("gallery.png", "GALLERY");
    results[1].hintDistance = 0.004;
    results[1].maxBadFraction = 0.002;
    results[1].maxFlipMean = 0.05;
    results[1].difference = "differs in 3.2% of the pixels, most of them in the top left (80% of them)";
    results[2].visibility = stoa::Visibility::Hidden;
    results[2].renderedImage = results[1].renderedImage;
    results[2].referenceImage = results[1].referenceImage;
    results[2].heatMapImage = results[1].heatMapImage;
    results[3].programOutput = "Segmentation fault <core dumped>\n\x1b[31m";

    HtmlReportOptions options;
    options.title = "Report for <ada>";
    options.docsBaseUrl = "file:///home/ada/stoa/";
    std::string html = htmlReport(results, summarize(results), options);

    CHECK(html.rfind("<!DOCTYPE html>\n<html", 0) == 0);
    CHECK(html.substr(html.size() - 8) == "</html>\n");
    CHECK(find(html, "<title>Report for &lt;ada&gt;</title>") != std::string::npos);
    CHECK(find(html, "score: 5 / 13") < find(html, "<section"));
    // Failures first: both failed cases, then the error, then the pass.
    CHECK(find(html, "02_shading/highlights") < find(html, "02_shading/crash"));
    CHECK(find(html, "02_shading/secret") < find(html, "02_shading/crash"));
    CHECK(find(html, "02_shading/crash") < find(html, "02_shading/sun"));
    // Escaped text; images as data URIs (base64 of "YOURS", "REF", "HEAT"); nothing loaded from elsewhere.
    CHECK(find(html, "3.2% pixels off &lt;max 200&gt; &amp; &quot;more&quot;") != std::string::npos);
    CHECK(find(html, "<max 200>") == std::string::npos);
    CHECK(find(html, "src=\"data:image/png;base64,WU9VUlM=\"") != std::string::npos);
    CHECK(find(html, "src=\"data:image/png;base64,UkVG\"") != std::string::npos);
    CHECK(find(html, "src=\"data:image/png;base64,SEVBVA==\"") != std::string::npos);
    CHECK(find(html, "src=\"http") == std::string::npos);
    CHECK(find(html, "<link") == std::string::npos);
    CHECK(find(html, "<script") == std::string::npos);
    // The metrics, and the hint with its link.
    CHECK(find(html, "<td class=\"over\">3.20%</td><td>0.20%</td>") != std::string::npos);
    CHECK(find(html, "<td>0.042</td><td>0.050</td>") != std::string::npos);
    CHECK(find(html, "Where: differs in 3.2% of the pixels, most of them in the top left") != std::string::npos);
    // The gallery picture beside the hint, with how close the match is; the heat map's legend.
    CHECK(find(html, "src=\"data:image/png;base64,R0FMTEVSWQ==\"") != std::string::npos);
    CHECK(find(html, "FLIP mean 0.004 from its picture, 0.042 from the reference") != std::string::npos);
    CHECK(find(html, "class=\"legend\" style=\"background: linear-gradient(") != std::string::npos);
    CHECK(find(html, "<code>no_half_vector</code>") != std::string::npos);
    CHECK(find(html, "Use H = normalize(L + V) &lt;not R&gt;.") != std::string::npos);
    CHECK(find(html, "href=\"file:///home/ada/stoa/docs/labs/02_shading.md#the-half-vector\"") != std::string::npos);
    // The hidden case shows the student's image but not the reference or the heat map.
    std::size_t secret = find(html, "id=\"02_shading-secret\"");
    std::string secretSection = html.substr(secret, html.find("</section>", secret) - secret);
    CHECK(secretSection.find("WU9VUlM=") != std::string::npos);
    CHECK(secretSection.find("UkVG") == std::string::npos);
    CHECK(secretSection.find("SEVBVA==") == std::string::npos);
    // The crashed program's output, escaped and without the terminal escape.
    CHECK(find(html, "Segmentation fault &lt;core dumped&gt;") != std::string::npos);
    CHECK(find(html, "\x1b") == std::string::npos);

    options.showHiddenReferences = true;
    std::string instructor = htmlReport(results, summarize(results), options);
    std::size_t at = find(instructor, "id=\"02_shading-secret\"");
    CHECK(instructor.substr(at, instructor.find("</section>", at) - at).find("UkVG") != std::string::npos);
}

TEST_CASE("writeHtmlReport writes the page and names a path it cannot write", "[grader][report][html]") {
    stoa::test::TempFolder folder("html-write");
    std::vector<GradeResult> results = {result("sun", GradeStatus::Passed, 5, 5, "")};
    std::filesystem::path path = folder / "out/report.html";
    writeHtmlReport(path, results, summarize(results));
    std::ifstream file(path);
    std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    CHECK(text == htmlReport(results, summarize(results)));
    folder.write("plain-file", "x");
    CHECK_THROWS_WITH(writeHtmlReport(folder / "plain-file/report.html", results, summarize(results)),
                      Catch::Contains("plain-file/report.html"));
}

TEST_CASE("docsLink: the built site's page when it has one, else the Markdown", "[grader][report][html]") {
    stoa::test::TempFolder folder;
    HtmlReportOptions options;
    options.docsBaseUrl = "file:///home/me/stoa/";
    const std::string hint = "docs/labs/02_shading.md#the-half-vector";
    // No site: the Markdown.
    CHECK(docsLink(hint, options) == "file:///home/me/stoa/docs/labs/02_shading.md#the-half-vector");
    CHECK(findDocsSite(folder.path(), folder.path() / "build" / "bin").empty());

    // A site without that page: still the Markdown.
    folder.write("site/index.html", "<html></html>");
    options.siteDir = findDocsSite(folder.path(), folder.path() / "build" / "bin");
    REQUIRE(options.siteDir == folder.path() / "site");
    CHECK(docsLink(hint, options) == "file:///home/me/stoa/docs/labs/02_shading.md#the-half-vector");

    // With the page: MkDocs's labs/02_shading/index.html, the anchor kept.
    folder.write("site/labs/02_shading/index.html", "<html></html>");
    const std::string page = std::filesystem::absolute(folder.path() / "site" / "labs" / "02_shading" / "index.html")
                                 .lexically_normal()
                                 .generic_string();
    CHECK(docsLink(hint, options) == "file://" + page + "#the-half-vector");
    CHECK(docsLink("docs/index.md", options) ==
          "file://" + std::filesystem::absolute(folder.path() / "site" / "index.html").lexically_normal().generic_string());

    // The docs test's site beside the build's bin folder is found too.
    stoa::test::TempFolder other;
    other.write("build/site/index.html", "<html></html>");
    CHECK(findDocsSite(other.path(), other.path() / "build" / "bin") == other.path() / "build" / "site");
}
