#include "HtmlReport.hpp"

#include "Base64.hpp"
#include "Escape.hpp"
#include "HeatMapLegend.hpp"
#include "ReportFile.hpp"

#include <algorithm>
#include <cstdio>

namespace stoa::grader {

namespace {

constexpr std::size_t kOutputBytesShown = 4096;

// Plain CSS: readable in light and dark mode, images side by side, wrapping on
// narrow windows. Pixelated scaling, so single-pixel differences stay visible.
const char* const kStyle = R"(
:root { color-scheme: light dark; --line: #8884; --muted: #888; }
body { font: 15px/1.45 system-ui, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; }
h1 { margin-bottom: 0.2em; }
.score { font-size: 1.6em; font-weight: 600; }
table { border-collapse: collapse; margin: 0.6em 0; }
td, th { border-bottom: 1px solid var(--line); padding: 0.25em 0.8em 0.25em 0; text-align: left; }
section.case { border: 1px solid var(--line); border-left-width: 6px; border-radius: 6px; padding: 0.6em 1em;
               margin: 1em 0; }
section.case h2 { font-size: 1.1em; margin: 0.2em 0; }
.badge { display: inline-block; border-radius: 4px; padding: 0 0.5em; font-size: 0.85em; font-weight: 600;
         color: #fff; vertical-align: middle; }
.passed { border-left-color: #2e7d32; } .passed .badge { background: #2e7d32; }
.failed { border-left-color: #c62828; } .failed .badge { background: #c62828; }
.error { border-left-color: #6a1b9a; } .error .badge { background: #6a1b9a; }
.not-attempted { border-left-color: #757575; } .not-attempted .badge { background: #757575; }
.no-reference { border-left-color: #ef6c00; } .no-reference .badge { background: #ef6c00; }
.hint { background: #fff8e1; color: #3e2a00; border-radius: 4px; padding: 0.5em 0.8em; margin: 0.5em 0; }
.hint a { color: #6d4c00; }
.hint .images { margin-top: 0.4em; }
.legend { width: 340px; max-width: 100%; height: 12px; border: 1px solid var(--line); }
.legend-labels { display: flex; justify-content: space-between; width: 340px; max-width: 100%; }
.over { color: #c62828; font-weight: 600; }
.images { display: flex; flex-wrap: wrap; gap: 0.8em; }
figure { margin: 0; }
figure img { max-width: 340px; width: 100%; image-rendering: pixelated; border: 1px solid var(--line); }
figcaption { color: var(--muted); font-size: 0.85em; }
pre { background: #8881; padding: 0.5em; overflow-x: auto; white-space: pre-wrap; font-size: 0.85em; }
.muted { color: var(--muted); }
)";

int rank(GradeStatus status) {
    switch (status) {
    case GradeStatus::Failed: return 0;
    case GradeStatus::Error: return 1;
    case GradeStatus::NoReference: return 2;
    case GradeStatus::NotAttempted: return 3;
    case GradeStatus::Passed: return 4;
    }
    return 5;
}

// The CSS class of a status: "not attempted" -> "not-attempted".
std::string statusClass(GradeStatus status) {
    std::string name = statusName(status);
    std::replace(name.begin(), name.end(), ' ', '-');
    return name;
}

std::string number(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

std::string figure(const std::filesystem::path& image, const std::string& caption) {
    std::string uri = fileDataUri(image);
    if (uri.empty()) return "";
    return "<figure><img src=\"" + uri + "\" alt=\"" + htmlEscape(caption) + "\"><figcaption>" +
           htmlEscape(caption) + "</figcaption></figure>\n";
}

std::string metricsTable(const GradeResult& result) {
    const CompareMetrics& comparison = *result.metrics;
    auto cell = [](const std::string& value, bool over) {
        return "<td" + std::string(over ? " class=\"over\"" : "") + ">" + value + "</td>";
    };
    std::string html = "<table class=\"metrics\">\n<tr><th></th><th>yours</th><th>passes at most</th></tr>\n";
    html += "<tr><th>differing pixels (beyond the tolerance, after the one-pixel shift search)</th>" +
            cell(percentText(comparison.badFraction), comparison.badFraction > result.maxBadFraction) + "<td>" +
            percentText(result.maxBadFraction) + "</td></tr>\n";
    if (comparison.flipMean >= 0.0)
        html += "<tr><th>FLIP mean (0: no visible difference, 1: the largest)</th>" +
                cell(flipText(comparison.flipMean), comparison.flipMean > result.maxFlipMean) + "<td>" +
                flipText(result.maxFlipMean) + "</td></tr>\n";
    html += "<tr><th>mean difference (0-255)</th><td>" + number("%.2f", comparison.meanError) + "</td><td></td></tr>\n";
    html += "<tr><th>largest difference (0-255)</th><td>" + std::to_string(comparison.maxError) + "</td><td></td></tr>\n";
    html += "</table>\n";
    return html;
}

std::string hintBox(const GradeResult& result, const HtmlReportOptions& options) {
    std::string html = "<div class=\"hint\"><strong>Hint (a suggestion, not a verdict):</strong> this picture looks "
                       "like the known mistake <code>" + htmlEscape(result.hintMistake) + "</code>";
    if (result.hintDistance >= 0.0 && result.metrics && result.metrics->flipMean >= 0.0)
        html += " (FLIP mean " + flipText(result.hintDistance) + " from its picture, " +
                flipText(result.metrics->flipMean) + " from the reference)";
    html += ". " + htmlEscape(result.hint);
    if (!result.hintDocs.empty())
        html += " <a href=\"" + htmlEscape(docsLink(result.hintDocs, options)) + "\">Read " +
                htmlEscape(result.hintDocs) + "</a>";
    std::string images = figure(result.renderedImage, "yours") +
                         figure(result.hintImage, "the known mistake " + result.hintMistake);
    if (!images.empty()) html += "<div class=\"images\">\n" + images + "</div>\n";
    return html + "</div>\n";
}

std::string legend() {
    return "<figure><div class=\"legend\" style=\"background: " + heatMapLegendGradient() +
           "\"></div><div class=\"legend-labels\"><span>0 (same)</span><span>0.5</span><span>1 (most "
           "different)</span></div><figcaption>heat map colours: FLIP error per pixel</figcaption></figure>\n";
}

std::string outputTail(const std::string& output) {
    if (output.size() <= kOutputBytesShown) return output;
    return "[...]\n" + output.substr(output.size() - kOutputBytesShown);
}

std::string caseSection(const GradeResult& result, const HtmlReportOptions& options) {
    std::string html = "<section class=\"case " + statusClass(result.status) + "\" id=\"" +
                       htmlEscape(result.lab + "-" + result.caseName) + "\">\n";
    html += "<h2>" + htmlEscape(result.fullName()) + " <span class=\"badge\">" + htmlEscape(statusName(result.status)) +
            "</span> <span class=\"muted\">" + formatPoints(result.points) + " / " + formatPoints(result.maxPoints) +
            " points, " + number("%.1f", result.seconds) + " s" +
            (result.visibility == Visibility::Hidden ? ", hidden case" : "") + "</span></h2>\n";
    if (!result.reason.empty()) html += "<p>" + htmlEscape(result.reason) + "</p>\n";
    if (!result.difference.empty()) html += "<p>Where: " + htmlEscape(result.difference) + "</p>\n";
    if (result.hasHint()) html += hintBox(result, options);
    if (result.metrics) html += metricsTable(result);

    bool showReference = result.visibility != Visibility::Hidden || options.showHiddenReferences;
    std::string images = figure(result.renderedImage, "yours");
    if (showReference) {
        images += figure(result.referenceImage, "reference");
        std::string heatMap = figure(result.heatMapImage, "heat map (brighter: more different)");
        if (!heatMap.empty()) images += heatMap + legend();
    }
    if (!images.empty()) html += "<div class=\"images\">\n" + images + "</div>\n";
    if (!showReference) html += "<p class=\"muted\">The reference of a hidden case is not shown.</p>\n";

    bool showOutput = result.status == GradeStatus::Error || result.status == GradeStatus::NotAttempted;
    if (showOutput && !result.programOutput.empty())
        html += "<details><summary>the program's output</summary><pre>" +
                htmlEscape(outputTail(result.programOutput)) + "</pre></details>\n";
    return html + "</section>\n";
}

std::string totalsSection(const Totals& totals) {
    std::string html = "<p class=\"score\">score: " + formatPoints(totals.points) + " / " +
                       formatPoints(totals.maxPoints) + "</p>\n<p>" + htmlEscape(totals.statuses.describe()) +
                       "</p>\n";
    html += "<table class=\"totals\">\n<tr><th>lab</th><th>points</th><th>cases</th></tr>\n";
    for (const LabTotals& lab : totals.labs)
        html += "<tr><td>" + htmlEscape(lab.lab) + "</td><td>" + formatPoints(lab.points) + " / " +
                formatPoints(lab.maxPoints) + "</td><td>" + htmlEscape(lab.statuses.describe()) + "</td></tr>\n";
    html += "</table>\n";
    for (const std::string& line : hints(totals)) html += "<p>" + htmlEscape(line) + "</p>\n";
    return html;
}

} // namespace

std::string docsLink(const std::string& docsPath, const HtmlReportOptions& options) {
    // "docs/labs/02_shading.md#anchor" -> the page "labs/02_shading" and "#anchor".
    const std::size_t hash = docsPath.find('#');
    const std::string file = docsPath.substr(0, hash);
    const std::string anchor = hash == std::string::npos ? "" : docsPath.substr(hash);
    const std::string prefix = "docs/", suffix = ".md";
    if (!options.siteDir.empty() && file.rfind(prefix, 0) == 0 && file.size() > prefix.size() + suffix.size() &&
        file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0) {
        std::string page = file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
        // MkDocs writes page.md as page/index.html, and index.md as index.html.
        std::filesystem::path html = page == "index" ? options.siteDir / "index.html"
                                                     : options.siteDir / page / "index.html";
        std::error_code error;
        if (std::filesystem::is_regular_file(html, error))
            return "file://" + std::filesystem::absolute(html).lexically_normal().generic_string() + anchor;
    }
    return options.docsBaseUrl + docsPath;
}

std::filesystem::path findDocsSite(const std::filesystem::path& sourceDir, const std::filesystem::path& binDir) {
    for (const std::filesystem::path& site : {sourceDir / "site", binDir.parent_path() / "site"}) {
        std::error_code error;
        if (!site.empty() && std::filesystem::is_regular_file(site / "index.html", error)) return site;
    }
    return {};
}

std::vector<std::size_t> failuresFirst(const std::vector<GradeResult>& results) {
    std::vector<std::size_t> order(results.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return rank(results[a].status) < rank(results[b].status);
    });
    return order;
}

std::string htmlReport(const std::vector<GradeResult>& results, const Totals& totals,
                       const HtmlReportOptions& options) {
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
                       htmlEscape(options.title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
    html += "<h1>" + htmlEscape(options.title) + "</h1>\n";
    html += totalsSection(totals);
    if (results.empty()) html += "<p>No case was graded.</p>\n";
    for (std::size_t index : failuresFirst(results)) html += caseSection(results[index], options);
    html += "</body>\n</html>\n";
    return html;
}

void writeHtmlReport(const std::filesystem::path& path, const std::vector<GradeResult>& results,
                     const Totals& totals, const HtmlReportOptions& options) {
    writeReportFile(path, htmlReport(results, totals, options), "the HTML report");
}

} // namespace stoa::grader
