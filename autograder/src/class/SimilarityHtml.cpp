// similarity.html and similarity.json: the ranked pairs of each lab, and for
// the first of them the runs they share, side by side. Every line of student
// code and every name is escaped. Declared in Similarity.hpp.

#include "Similarity.hpp"

#include "Escape.hpp"
#include "JsonWriter.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace stoa::grader {

namespace {

constexpr int kRunLinesShown = 80;   // lines of one side of a run before "..."

const char* const kStyle = R"(
:root { color-scheme: light dark; --line: #8884; --muted: #888; }
body { font: 15px/1.4 system-ui, sans-serif; max-width: 1400px; margin: 1em auto; padding: 0 1em; }
h1 { font-size: 1.6em; margin: 0.2em 0; } h2 { font-size: 1.2em; margin: 1em 0 0.3em; }
h3 { font-size: 1.05em; margin: 0.8em 0 0.2em; }
.note { background: #fff8e1; color: #3e2a00; border-radius: 4px; padding: 0.6em 0.9em; max-width: 60em; }
table { border-collapse: collapse; margin: 0.4em 0; }
td, th { border-bottom: 1px solid var(--line); padding: 0.2em 0.8em 0.2em 0; text-align: left; vertical-align: top; }
td.num, th.num { text-align: right; }
.share { display: inline-block; height: 0.7em; background: #3a6fb0; vertical-align: middle; }
.runs { display: grid; grid-template-columns: 1fr 1fr; gap: 0.3em 1em; }
.runs > div { min-width: 0; }
pre { margin: 0; padding: 0.4em; background: #8881; overflow-x: auto; font-size: 0.8em; line-height: 1.3; }
.given { color: var(--muted); }
.where { color: var(--muted); font-size: 0.85em; }
section.lab { border-top: 2px solid var(--line); margin-top: 1.2em; }
.muted { color: var(--muted); }
)";

std::string escape(const std::string& text) { return htmlEscape(text); }

// Lines first..last (1-based) of `text`, each with its file and line, given code greyed.
std::string runLines(const StudentText& text, int first, int last) {
    std::ostringstream html;
    const int count = static_cast<int>(text.lines.size());
    first = std::max(1, first);
    last = std::min(count, last);
    if (first > last) return "<pre></pre>";
    const auto& start = text.origin[static_cast<std::size_t>(first - 1)];
    html << "<div class=\"where\">" << escape(text.student) << ": " << escape(start.first) << ":" << start.second
         << "</div><pre>";
    for (int line = first; line <= last && line < first + kRunLinesShown; ++line) {
        std::size_t i = static_cast<std::size_t>(line - 1);
        char number[16];
        std::snprintf(number, sizeof number, "%4d  ", text.origin[i].second);
        html << (text.given[i] ? "<span class=\"given\">" : "<span>") << number << escape(text.lines[i]) << "</span>\n";
    }
    if (last >= first + kRunLinesShown) html << "...\n";
    html << "</pre>";
    return html.str();
}

void pairDetail(std::ostringstream& html, const LabSimilarity& lab, const SimilarPair& pair, int rank) {
    const StudentText& a = lab.texts.at(pair.a);
    const StudentText& b = lab.texts.at(pair.b);
    html << "<h3 id=\"" << escape(lab.lab) << "-" << rank << "\">" << rank << ". " << escape(pair.a) << " and "
         << escape(pair.b) << ": " << static_cast<int>(pair.score + 0.5) << "% shared</h3>";
    if (pair.runs.empty()) {
        html << "<p class=\"muted\">SIM listed no run for this pair on its own.</p>";
        return;
    }
    html << "<div class=\"runs\">";
    for (const SharedRun& run : pair.runs)
        html << "<div>" << runLines(a, run.firstA, run.lastA) << "</div><div>" << runLines(b, run.firstB, run.lastB)
             << "<div class=\"where\">" << run.tokens << " tokens in common</div></div>";
    html << "</div>";
}

void labSection(std::ostringstream& html, const LabSimilarity& lab, const SimilarityOptions& options) {
    html << "<section class=\"lab\"><h2>" << escape(lab.lab) << "</h2>";
    if (!lab.error.empty()) {
        html << "<p>Not compared: " << escape(lab.error) << "</p></section>";
        return;
    }
    std::string files;
    for (const std::string& file : lab.files) files += (files.empty() ? "" : ", ") + file;
    html << "<p class=\"muted\">" << escape(files) << " compared with " << escape(lab.tool) << ": "
         << lab.pairsCompared << " pairs of " << lab.texts.size() - lab.leftOut.size() << " students";
    if (!lab.leftOut.empty())
        html << "; " << lab.leftOut.size() << " left out with fewer than " << options.minimumTokens
             << " tokens of their own";
    html << ".</p>";
    if (lab.pairs.empty()) {
        html << "<p>No pair shares a run of " << options.minimumRun << " tokens.</p></section>";
        return;
    }
    html << "<table><tr><th class=\"num\">rank</th><th>students</th><th class=\"num\">shared</th><th></th>"
            "<th class=\"num\">of the first's code</th><th class=\"num\">of the second's</th></tr>";
    const int listed = std::min(static_cast<int>(lab.pairs.size()), options.pairsListed);
    for (int i = 0; i < listed; ++i) {
        const SimilarPair& pair = lab.pairs[static_cast<std::size_t>(i)];
        std::string names = escape(pair.a) + " and " + escape(pair.b);
        if (i < options.pairsShown) names = "<a href=\"#" + escape(lab.lab) + "-" + std::to_string(i + 1) + "\">" + names + "</a>";
        html << "<tr><td class=\"num\">" << i + 1 << "</td><td>" << names << "</td><td class=\"num\">"
             << static_cast<int>(pair.score + 0.5) << "%</td><td><span class=\"share\" style=\"width:"
             << static_cast<int>(pair.score) << "px\"></span></td><td class=\"num\">" << pair.percentA
             << "%</td><td class=\"num\">" << pair.percentB << "%</td></tr>";
    }
    html << "</table>";
    if (static_cast<int>(lab.pairs.size()) > listed)
        html << "<p class=\"muted\">" << lab.pairs.size() - static_cast<std::size_t>(listed)
             << " more pairs share something; similarity.json lists them all.</p>";
    for (int i = 0; i < std::min(listed, options.pairsShown); ++i)
        pairDetail(html, lab, lab.pairs[static_cast<std::size_t>(i)], i + 1);
    html << "</section>";
}

} // namespace

std::string similarityHtml(const std::vector<LabSimilarity>& labs, const SimilarityOptions& options) {
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Similar submissions</title><style>"
         << kStyle << "</style></head><body><h1>Which submissions look alike</h1>";
    html << "<p class=\"note\"><b>This page ranks; it does not accuse.</b> Short functions whose correct solutions "
            "are alike are expected: two students who both wrote a correct look-at matrix share much of it. A pair "
            "near the top is a pair to read, side by side, before anything else. The stubs' given code never counts "
            "(greyed below). SIM compares tokens: renamed identifiers, another layout and comments change nothing, "
            "and reordered functions are found one by one. A shared run has at least "
         << options.minimumRun << " tokens. <i>shared</i> is the share of both students' own code that the other "
            "has.</p>";
    for (const LabSimilarity& lab : labs) labSection(html, lab, options);
    html << "</body></html>\n";
    return html.str();
}

std::string similarityJson(const std::vector<LabSimilarity>& labs) {
    JsonWriter json;
    json.beginObject().key("labs").beginArray();
    for (const LabSimilarity& lab : labs) {
        json.beginObject().key("lab").value(lab.lab).key("tool").value(lab.tool);
        if (!lab.error.empty()) json.key("error").value(lab.error);
        json.key("students").value(static_cast<int>(lab.texts.size()));
        json.key("pairs_compared").value(lab.pairsCompared);
        json.key("left_out").beginArray();
        for (const std::string& student : lab.leftOut) json.value(student);
        json.endArray();
        json.key("pairs").beginArray();
        for (const SimilarPair& pair : lab.pairs) {
            json.beginObject().key("a").value(pair.a).key("b").value(pair.b).key("score").value(pair.score);
            json.key("percent_a").value(pair.percentA).key("percent_b").value(pair.percentB).endObject();
        }
        json.endArray().endObject();
    }
    json.endArray().endObject();
    return json.text() + "\n";
}

} // namespace stoa::grader
