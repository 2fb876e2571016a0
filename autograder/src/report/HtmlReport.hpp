#pragma once
// The grade report as one self-contained HTML page: the totals at the top, then
// one section per case, failures first, each with the student's image, the
// reference and the heat map (embedded as base64 data URIs, so the file can be
// mailed or uploaded alone), the metric values, the status and reason, and the
// known-mistake hint with a link to the docs section that explains it. The page
// loads nothing from elsewhere (inline CSS, no scripts), and every string from a
// result is HTML-escaped.

#include "GradeResult.hpp"
#include "Report.hpp"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

struct HtmlReportOptions {
    std::string title = "stoa-grade report";
    /// Put before a hint's docs path ("docs/labs/...md#anchor") to make its link,
    /// e.g. "file:///home/me/stoa/". Empty: the link is the docs path itself.
    std::string docsBaseUrl;
    /// The built docs site (`mkdocs build`'s output, e.g. <source>/site): a hint then links to
    /// its page (site/labs/02_shading/index.html#anchor), which a browser shows with the
    /// equations typeset; without one, or when it lacks the page, to the Markdown.
    std::filesystem::path siteDir;
    /// Hidden cases show the student's image only: their reference and heat map
    /// would reveal a case students are not meant to see. True shows them (for
    /// a report only instructors read).
    bool showHiddenReferences = false;
};

/// The link for a hint's docs path ("docs/labs/02_shading.md#the-half-vector"): the page of
/// the built site when `options.siteDir` has it (a file:// URL), else docsBaseUrl + the path.
std::string docsLink(const std::string& docsPath, const HtmlReportOptions& options);

/// The built docs site to link to: <sourceDir>/site or <binDir>/../site (the docs test's),
/// the first that has an index.html; empty when neither has.
std::filesystem::path findDocsSite(const std::filesystem::path& sourceDir, const std::filesystem::path& binDir);

/// The order the page lists the results in: failed, error, no reference, not
/// attempted, passed; the grader's order within each.
std::vector<std::size_t> failuresFirst(const std::vector<GradeResult>& results);

/// The page as text.
std::string htmlReport(const std::vector<GradeResult>& results, const Totals& totals,
                       const HtmlReportOptions& options = {});

/// Writes htmlReport() to `path` (its folder is created). Throws InputError when it cannot.
void writeHtmlReport(const std::filesystem::path& path, const std::vector<GradeResult>& results,
                     const Totals& totals, const HtmlReportOptions& options = {});

} // namespace stoa::grader
