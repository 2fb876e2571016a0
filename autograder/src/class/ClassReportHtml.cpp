// class.html: the class report as one static page. The histograms are inline
// SVG drawn here, the pass-rate bars plain CSS; no script, nothing loaded from
// elsewhere, so the file opens from a file manager and prints. Every text that
// comes from a submission or a results.json is escaped (students are
// untrusted). Declared in ClassReport.hpp.

#include "ClassReport.hpp"

#include "Escape.hpp"
#include "Report.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <sstream>

namespace stoa::grader {

namespace {

constexpr std::size_t kStudentsShown = 8;   // names listed before "and N more" (the rest in <details>)

const char* const kStyle = R"(
:root { color-scheme: light dark; --line: #8884; --muted: #888; --bar: #3a6fb0; }
body { font: 15px/1.4 system-ui, sans-serif; max-width: 1240px; margin: 1em auto; padding: 0 1em; }
h1 { margin: 0.2em 0; font-size: 1.6em; } h2 { font-size: 1.2em; margin: 0.8em 0 0.3em; }
h3 { font-size: 1.05em; margin: 0.8em 0 0.2em; }
.lead { margin: 0 0 0.6em; }
.top { display: flex; gap: 1.5em; align-items: flex-start; flex-wrap: wrap; }
.top .teach { flex: 1 1 640px; } .top .overall { flex: 0 0 360px; }
table { border-collapse: collapse; margin: 0.4em 0; }
td, th { border-bottom: 1px solid var(--line); padding: 0.2em 0.7em 0.2em 0; text-align: left; vertical-align: top; }
td.num, th.num { text-align: right; white-space: nowrap; }
td.who { width: 36%; }
.kind { display: inline-block; border-radius: 4px; padding: 0 0.45em; font-size: 0.8em; font-weight: 600;
        color: #fff; background: #757575; }
.kind.mistake { background: #b26a00; } .kind.case { background: #c62828; } .kind.check { background: #6a1b9a; }
.kind.compile { background: #37474f; }
.count { display: inline-block; height: 0.7em; background: #c62828; vertical-align: middle; margin-left: 0.3em; }
.rate { display: flex; width: 220px; height: 0.9em; border: 1px solid var(--line); }
.rate span { display: block; height: 100%; }
.r-passed { background: #2e7d32; } .r-failed { background: #c62828; } .r-not-attempted { background: #9e9e9e; }
.r-error { background: #6a1b9a; } .r-missing { background: #e0e0e0; }
.legend span { display: inline-block; width: 0.8em; height: 0.8em; margin: 0 0.2em 0 0.8em; vertical-align: middle; }
.grid { display: flex; flex-wrap: wrap; gap: 0.6em 1.2em; }
figure { margin: 0; } figure a { color: inherit; text-decoration: none; } figcaption { font-size: 0.85em; color: var(--muted); }
svg text { font: 11px system-ui, sans-serif; fill: currentColor; }
svg .bar { fill: var(--bar); } svg .axis { stroke: var(--muted); stroke-width: 1; }
section.lab { border-top: 2px solid var(--line); margin-top: 1.2em; }
.muted { color: var(--muted); } code { font-size: 0.9em; }
details summary { cursor: pointer; color: var(--muted); }
)";

std::string escape(const std::string& text) { return htmlEscape(text); }

std::string number(double value, int decimals = 1) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    std::string shown = text;
    if (shown.find('.') != std::string::npos) {
        while (shown.back() == '0') shown.pop_back();
        if (shown.back() == '.') shown.pop_back();
    }
    return shown;
}

std::string percent(double part, double whole) {
    return whole > 0.0 ? number(100.0 * part / whole, 0) + "%" : "-";
}

// A student's name for a URL path: unreserved characters kept, the rest %XX.
std::string urlPath(const std::string& path) {
    std::string encoded;
    for (unsigned char c : path) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/') {
            encoded += static_cast<char>(c);
        } else {
            char hex[4];
            std::snprintf(hex, sizeof hex, "%%%02X", c);
            encoded += hex;
        }
    }
    return encoded;
}

class Page {
public:
    explicit Page(const ClassSummary& summary) : m_summary(summary) {
        for (const StudentRecord& student : summary.students) m_links[student.student] = student.reportLink;
    }
    std::string render();

private:
    std::string studentLink(const std::string& student) const;
    std::string studentList(const std::vector<std::string>& students) const;
    std::string histogram(const ScoreDistribution& scores, const std::string& title, int width, int height) const;
    void teachAgain();
    void needsALook();
    void labSection(const LabSummary& lab);
    void caseTable(const LabSummary& lab);
    void problems(const LabSummary& lab);
    void studentsTable();

    const ClassSummary& m_summary;
    std::map<std::string, std::string> m_links;
    std::ostringstream m_html;
};

std::string Page::studentLink(const std::string& student) const {
    auto found = m_links.find(student);
    if (found == m_links.end() || found->second.empty()) return escape(student);
    return "<a href=\"" + escape(urlPath(found->second)) + "\">" + escape(student) + "</a>";
}

std::string Page::studentList(const std::vector<std::string>& students) const {
    std::string shown;
    std::string rest;
    for (std::size_t i = 0; i < students.size(); ++i)
        (i < kStudentsShown ? shown : rest) += (i == 0 || i == kStudentsShown ? "" : ", ") + studentLink(students[i]);
    if (rest.empty()) return shown;
    return shown + " <details><summary>and " + std::to_string(students.size() - kStudentsShown) + " more</summary>" +
           rest + "</details>";
}

// A histogram of the scores in bins of 10% of the maximum, full marks on their
// own, each bar labelled with its count.
std::string Page::histogram(const ScoreDistribution& scores, const std::string& title, int width, int height) const {
    const int left = 8;
    const int bottom = 30;
    const int top = 16;
    const int plotHeight = height - bottom - top;
    const double barWidth = double(width - 2 * left) / ScoreDistribution::kBins;
    int largest = 1;
    for (int count : scores.bins) largest = std::max(largest, count);
    std::ostringstream svg;
    svg << "<svg class=\"histogram\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\""
        << height << "\" viewBox=\"0 0 " << width << " " << height << "\" role=\"img\"><title>" << escape(title)
        << "</title>";
    for (int bin = 0; bin < ScoreDistribution::kBins; ++bin) {
        int count = scores.bins[static_cast<std::size_t>(bin)];
        double x = left + bin * barWidth;
        double barHeight = count > 0 ? std::max(2.0, double(plotHeight) * count / largest) : 0.0;
        double y = top + plotHeight - barHeight;
        svg << "<rect class=\"bar\" x=\"" << number(x + 1.5) << "\" y=\"" << number(y) << "\" width=\""
            << number(barWidth - 3.0) << "\" height=\"" << number(barHeight) << "\"><title>"
            << (bin == ScoreDistribution::kBins - 1 ? std::string("full marks")
                                                    : std::to_string(bin * 10) + "-" + std::to_string(bin * 10 + 9) + "%")
            << ": " << count << "</title></rect>";
        if (count > 0)
            svg << "<text x=\"" << number(x + barWidth / 2) << "\" y=\"" << number(y - 3)
                << "\" text-anchor=\"middle\">" << count << "</text>";
        if (bin % 2 == 0 || bin == ScoreDistribution::kBins - 1)
            svg << "<text x=\"" << number(x + barWidth / 2) << "\" y=\"" << (height - bottom + 13)
                << "\" text-anchor=\"middle\">" << (bin == ScoreDistribution::kBins - 1 ? "100" : std::to_string(bin * 10))
                << "</text>";
    }
    svg << "<line class=\"axis\" x1=\"" << left << "\" y1=\"" << (top + plotHeight) << "\" x2=\"" << (width - left)
        << "\" y2=\"" << (top + plotHeight) << "\"/>";
    svg << "<text x=\"" << width / 2 << "\" y=\"" << (height - 3) << "\" text-anchor=\"middle\">% of "
        << number(scores.maxPoints) << " points</text></svg>";
    return svg.str();
}

void Page::teachAgain() {
    const double classSize = static_cast<double>(m_summary.students.size());
    m_html << "<section class=\"teach\"><h2>What to teach again</h2>";
    if (m_summary.teachAgain.empty()) {
        m_html << "<p>Nothing: no case failed, no hint named a mistake, every lab compiled.</p>";
        needsALook();
        m_html << "</section>";
        return;
    }
    m_html << "<table><tr><th class=\"num\">students</th><th>what</th><th>lab</th><th>who</th></tr>";
    for (const TeachingPoint& point : m_summary.teachAgain) {
        int width = static_cast<int>(60.0 * point.students.size() / std::max(1.0, classSize) + 0.5);
        m_html << "<tr><td class=\"num\">" << point.students.size() << " <span class=\"muted\">("
               << percent(double(point.students.size()), classSize) << ")</span><span class=\"count\" style=\"width:"
               << width << "px\"></span></td><td><span class=\"kind " << point.kind << "\">" << point.kind
               << "</span> <b>" << escape(point.name) << "</b>";
        if (!point.text.empty()) m_html << "<br><span class=\"muted\">" << escape(point.text) << "</span>";
        if (!point.docs.empty()) m_html << " <code>" << escape(point.docs) << "</code>";
        m_html << "</td><td><a href=\"#lab-" << escape(urlPath(point.lab)) << "\">" << escape(point.lab)
               << "</a></td><td class=\"who\">" << studentList(point.students) << "</td></tr>";
    }
    m_html << "</table>";
    needsALook();
    m_html << "</section>";
}

// One line per lab where some students' work did not grade as it should:
// did not compile, timed out, not attempted; the names are in the lab's section.
void Page::needsALook() {
    std::string lines;
    for (const LabSummary& lab : m_summary.labs) {
        std::string parts;
        auto add = [&](std::size_t count, const char* what) {
            if (count > 0) parts += (parts.empty() ? "" : ", ") + std::to_string(count) + " " + what;
        };
        add(lab.notCompiled.size(), "did not compile");
        add(lab.timedOut.size(), "timed out");
        add(lab.notAttempted.size(), "not attempted");
        if (!parts.empty())
            lines += "<li><a href=\"#lab-" + escape(urlPath(lab.lab)) + "\">" + escape(lab.lab) + "</a>: " + parts + "</li>";
    }
    if (!m_summary.notGraded.empty())
        lines += "<li><a href=\"#not-graded\">" + std::to_string(m_summary.notGraded.size()) +
                 " submissions not graded</a> (no labs/ folder, configure failed, unreadable)</li>";
    if (!lines.empty()) m_html << "<h2>Needs a look</h2><ul>" << lines << "</ul>";
}

void Page::caseTable(const LabSummary& lab) {
    const int classSize = static_cast<int>(m_summary.students.size());
    m_html << "<h3>Cases, lowest pass rate first</h3><p class=\"legend muted\"><span class=\"r-passed\"></span>passed"
              "<span class=\"r-failed\"></span>wrong<span class=\"r-not-attempted\"></span>not attempted"
              "<span class=\"r-error\"></span>error or timeout<span class=\"r-missing\"></span>no result (did not "
              "compile)</p><table><tr><th>case</th><th class=\"num\">pass rate</th><th></th><th class=\"num\">wrong"
              "</th><th>what it checks</th></tr>";
    for (const CaseSummary& summary : lab.cases) {
        m_html << "<tr><td>" << escape(summary.name) << (summary.propertyCheck ? " <span class=\"kind check\">check</span>" : "")
               << "</td><td class=\"num\">" << percent(summary.passed, classSize) << "</td><td><div class=\"rate\">";
        const std::pair<const char*, int> parts[] = {{"passed", summary.passed}, {"failed", summary.failed},
                                                     {"not-attempted", summary.notAttempted},
                                                     {"error", summary.error}, {"missing", summary.missing}};
        for (const auto& [name, count] : parts)
            if (count > 0 && classSize > 0)
                m_html << "<span class=\"r-" << name << "\" style=\"width:" << number(100.0 * count / classSize, 2)
                       << "%\" title=\"" << count << "\"></span>";
        m_html << "</div></td><td class=\"num\">" << summary.failed << "</td><td class=\"muted\">"
               << escape(summary.description) << "</td></tr>";
    }
    m_html << "</table>";
}

void Page::problems(const LabSummary& lab) {
    if (!lab.mistakes.empty()) {
        m_html << "<h3>Mistakes the hints named</h3><table><tr><th class=\"num\">students</th><th>mistake</th>"
                  "<th>who</th></tr>";
        for (const MistakeSummary& mistake : lab.mistakes) {
            std::string cases;
            for (const std::string& name : mistake.cases) cases += (cases.empty() ? "" : ", ") + name;
            m_html << "<tr><td class=\"num\">" << mistake.students.size() << "</td><td><b>" << escape(mistake.name)
                   << "</b> <span class=\"muted\">(on " << escape(cases) << ")</span><br>" << escape(mistake.hint)
                   << "</td><td class=\"who\">" << studentList(mistake.students) << "</td></tr>";
        }
        m_html << "</table>";
    }
    if (!lab.notCompiled.empty()) {
        m_html << "<h3>Did not compile (" << lab.notCompiled.size() << ")</h3><table>";
        for (const StudentProblem& problem : lab.notCompiled)
            m_html << "<tr><td>" << studentLink(problem.student) << "</td><td><code>" << escape(problem.detail)
                   << "</code></td></tr>";
        m_html << "</table>";
    }
    if (!lab.timedOut.empty()) {
        m_html << "<h3>Timed out (" << lab.timedOut.size() << ")</h3><table>";
        for (const StudentProblem& problem : lab.timedOut)
            m_html << "<tr><td>" << studentLink(problem.student) << "</td><td>" << escape(problem.detail) << "</td></tr>";
        m_html << "</table>";
    }
    if (!lab.notAttempted.empty())
        m_html << "<h3>Not attempted (" << lab.notAttempted.size() << ")</h3><p>" << studentList(lab.notAttempted)
               << "</p>";
}

void Page::labSection(const LabSummary& lab) {
    m_html << "<section class=\"lab\" id=\"lab-" << escape(urlPath(lab.lab)) << "\"><h2>" << escape(lab.lab)
           << "</h2><div class=\"top\"><figure>"
           << histogram(lab.scores, lab.lab + ": scores", 360, 170) << "<figcaption>mean " << number(lab.scores.mean)
           << ", median " << number(lab.scores.median) << " of " << number(lab.scores.maxPoints)
           << " points</figcaption></figure><div>";
    caseTable(lab);
    m_html << "</div></div>";
    problems(lab);
    m_html << "</section>";
}

void Page::studentsTable() {
    m_html << "<section id=\"students\"><h2>Every student</h2><table><tr><th>student</th><th class=\"num\">total</th>";
    for (const LabSummary& lab : m_summary.labs) m_html << "<th class=\"num\">" << escape(lab.lab.substr(0, 2)) << "</th>";
    m_html << "<th>status</th></tr>";
    for (const StudentRecord& student : m_summary.students) {
        m_html << "<tr><td>" << studentLink(student.student) << "</td><td class=\"num\">" << formatPoints(student.points)
               << " / " << formatPoints(student.maxPoints) << "</td>";
        for (const LabSummary& lab : m_summary.labs) {
            auto found = student.labs.find(lab.lab);
            m_html << "<td class=\"num\">" << formatPoints(found == student.labs.end() ? 0.0 : found->second.points)
                   << "</td>";
        }
        m_html << "<td>" << escape(student.status) << "</td></tr>";
    }
    m_html << "</table></section>";
}

std::string Page::render() {
    const ScoreDistribution& overall = m_summary.overall;
    m_html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Class report: "
           << m_summary.students.size() << " students</title><style>" << kStyle << "</style></head><body>";
    m_html << "<h1>Class report: " << m_summary.students.size() << " students</h1><p class=\"lead\">Mean total <b>"
           << number(overall.mean) << "</b> of " << number(overall.maxPoints) << " points ("
           << percent(overall.mean, overall.maxPoints) << "), median " << number(overall.median) << ". From "
           << escape(m_summary.source) << ". <a href=\"#scores\">Scores per lab</a> &middot; <a href=\"#students\">every "
              "student</a>";
    if (!m_summary.notGraded.empty())
        m_html << " &middot; <a href=\"#not-graded\"><b>" << m_summary.notGraded.size() << " not graded</b></a>";
    m_html << "</p><div class=\"top\">";
    teachAgain();
    m_html << "<figure class=\"overall\">" << histogram(overall, "total scores", 360, 200)
           << "<figcaption>Total scores: how many students in each tenth of the maximum</figcaption></figure></div>";

    m_html << "<section id=\"scores\"><h2>Scores per lab</h2><div class=\"grid\">";
    for (const LabSummary& lab : m_summary.labs)
        m_html << "<figure><a href=\"#lab-" << escape(urlPath(lab.lab)) << "\">"
               << histogram(lab.scores, lab.lab + ": scores", 280, 140) << "</a><figcaption>" << escape(lab.lab)
               << ": mean " << number(lab.scores.mean) << " of " << number(lab.scores.maxPoints) << "</figcaption></figure>";
    m_html << "</div></section>";

    if (!m_summary.notGraded.empty() || !m_summary.unreadable.empty()) {
        m_html << "<section id=\"not-graded\"><h2>Not graded</h2><table>";
        for (const StudentProblem& problem : m_summary.notGraded)
            m_html << "<tr><td>" << studentLink(problem.student) << "</td><td>" << escape(problem.detail) << "</td></tr>";
        for (const std::string& why : m_summary.unreadable)
            m_html << "<tr><td>(unreadable)</td><td><code>" << escape(why) << "</code></td></tr>";
        m_html << "</table></section>";
    }
    for (const LabSummary& lab : m_summary.labs) labSection(lab);
    studentsTable();
    m_html << "</body></html>\n";
    return m_html.str();
}

} // namespace

std::string classHtml(const ClassSummary& summary) { return Page(summary).render(); }

} // namespace stoa::grader
