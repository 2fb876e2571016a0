#include "Report.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace stoa::grader {

namespace {

// The lab a not-attempted case waits for: the one its stub belongs to when the
// lab program names it ("not implemented: forward(FirstPersonState) (lab
// 01_transforms)", NotImplemented::describe()), else the case's own lab.
std::string labToStartWith(const GradeResult& result) {
    const std::string marker = " (lab ";
    const std::size_t at = result.reason.rfind(marker);
    if (at == std::string::npos || result.reason.empty() || result.reason.back() != ')') return result.lab;
    const std::string lab = result.reason.substr(at + marker.size(), result.reason.size() - at - marker.size() - 1);
    return lab.empty() || lab.find(' ') != std::string::npos ? result.lab : lab;
}

constexpr std::size_t kLineWidth = 100;   // the report is wrapped to this many columns
constexpr int kOutputLinesShown = 12;

// The case column: a cascade run's cases are marked.
std::string caseLabel(const GradeResult& result) {
    return result.cascade ? result.caseName + " [cascade]" : result.caseName;
}

std::string padded(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

std::string format(const char* pattern, double value) {
    char text[32];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// The last `count` lines of a program's output, each indented.
std::string lastLines(const std::string& output, int count) {
    std::vector<std::string> lines;
    std::istringstream stream(output);
    for (std::string line; std::getline(stream, line);) lines.push_back(line);
    while (!lines.empty() && lines.back().find_first_not_of(" \t\r") == std::string::npos) lines.pop_back();
    std::size_t first = lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0;
    std::string text;
    for (std::size_t i = first; i < lines.size(); ++i) text += "      | " + lines[i] + "\n";
    return text;
}

// The share of differing pixels and the FLIP mean of a compared case ("" for one that was not).
std::string pixelsCell(const GradeResult& result) {
    return result.metrics ? percentText(result.metrics->badFraction) : "";
}
std::string flipCell(const GradeResult& result) {
    if (!result.metrics || result.metrics->flipMean < 0.0) return "";
    return flipText(result.metrics->flipMean);
}

bool sameThresholds(const std::vector<GradeResult>& results) {
    for (const GradeResult& result : results)
        if (result.maxBadFraction != results.front().maxBadFraction ||
            result.maxFlipMean != results.front().maxFlipMean)
            return false;
    return true;
}

// The labs whose every counted case is not attempted: one line each.
bool collapsed(const Totals& totals, const std::string& lab) {
    for (const LabTotals& entry : totals.labs)
        if (entry.lab == lab) return entry.nothingAttempted();
    return false;
}

// A cascade run's case that says nothing new: its lab's own stubs are untouched
// too (every counted case and this one not attempted). A fresh clone shows no
// cascade rows at all.
bool quietCascade(const Totals& totals, const GradeResult& result) {
    return result.cascade && !result.counted && result.status == GradeStatus::NotAttempted &&
           collapsed(totals, result.lab);
}

// Errors of one lab with the same reason and output are detailed once.
struct ErrorGroup {
    std::string lab;
    std::string reason;
    std::string output;
    std::vector<std::string> cases;
};

} // namespace

std::string percentText(double fraction) {
    double percent = 100.0 * fraction;
    if (percent == 0.0) return "0%";
    if (percent >= 10.0) return format("%.1f%%", percent);
    if (percent >= 0.1) return format("%.2f%%", percent);
    return format("%.3f%%", percent);
}

std::string flipText(double flipMean) {
    return flipMean == 0.0 ? "0" : format("%.3f", flipMean);
}

std::vector<std::string> wrapped(const std::string& text, std::size_t width, std::size_t indent,
                                 std::size_t firstIndent) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    std::string line = std::string(firstIndent, ' ');
    bool empty = true;
    for (std::string word; stream >> word;) {
        if (!empty && line.size() + 1 + word.size() > width) {
            lines.push_back(line);
            line = std::string(indent, ' ');
            empty = true;
        }
        line += (empty ? "" : " ") + word;
        empty = false;
    }
    if (!empty) lines.push_back(line);
    return lines;
}

int StatusCounts::total() const {
    int sum = 0;
    for (int count : counts) sum += count;
    return sum;
}

std::string StatusCounts::describe() const {
    std::string text;
    for (int i = 0; i < kStatusCount; ++i) {
        if (counts[i] == 0) continue;
        if (!text.empty()) text += ", ";
        text += std::to_string(counts[i]) + " " + statusName(static_cast<GradeStatus>(i));
    }
    return text.empty() ? "no cases" : text;
}

bool LabTotals::nothingAttempted() const {
    return statuses.total() > 0 && statuses[GradeStatus::NotAttempted] == statuses.total();
}

Totals summarize(const std::vector<GradeResult>& results) {
    Totals totals;
    for (const GradeResult& result : results) {
        auto lab = std::find_if(totals.labs.begin(), totals.labs.end(),
                                [&](const LabTotals& entry) { return entry.lab == result.lab; });
        if (lab == totals.labs.end()) {
            totals.labs.push_back(LabTotals{});
            totals.labs.back().lab = result.lab;
            lab = totals.labs.end() - 1;
        }
        if (result.cascade) {
            lab->hasCascade = true;
            lab->cascadePoints += result.points;
        } else {
            lab->ownPoints += result.points;
        }
        if (!result.counted) continue;
        lab->points += result.points;
        lab->maxPoints += result.maxPoints;
        lab->statuses.add(result.status);
        totals.points += result.points;
        totals.maxPoints += result.maxPoints;
        totals.statuses.add(result.status);
    }
    return totals;
}

bool allHaveStatus(const std::vector<GradeResult>& results, GradeStatus status) {
    return !results.empty() && std::all_of(results.begin(), results.end(),
                                           [&](const GradeResult& result) { return result.status == status; });
}

std::string formatPoints(double points) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", points);
    std::string formatted = text;
    formatted.erase(formatted.find_last_not_of('0') + 1);
    if (formatted.back() == '.') formatted.pop_back();
    return formatted == "-0" ? "0" : formatted;
}

namespace {

// "not implemented: F (lab L)" or "not implemented: F (path/to/file.glsl:7)" -> "F" or
// "F (file.glsl:7)": the stub a not-attempted case ran into, without folders.
std::string stubNamed(const std::string& reason) {
    std::string stub = reason.substr(0, reason.rfind(" (lab "));
    const std::string prefix = "not implemented: ";
    if (stub.compare(0, prefix.size(), prefix) != 0) return "";
    stub = stub.substr(prefix.size());
    const std::size_t open = stub.find(" (");
    const std::size_t slash = stub.rfind('/');
    if (open != std::string::npos && slash != std::string::npos && slash > open)
        stub = stub.substr(0, open + 2) + stub.substr(slash + 1);
    return stub;
}

} // namespace

namespace {

// The table's columns, sized to what they hold, and its pass limits when every
// case shares them.
struct TableLayout {
    std::size_t labWidth = 3, caseWidth = 4, statusWidth = 6, pointsWidth = 6, pixelsWidth = 16, flipWidth = 9;
    bool uniform = false;     // every case has the same thresholds
    bool known = false;       // some case has thresholds at all
    std::string pixelsLimit;  // "pass: <= 0.20%" under the header, when uniform and known
    std::string flipLimit;
    std::size_t rowStart() const { return labWidth + caseWidth + statusWidth + pointsWidth + 8; }
};

std::string pointsText(const GradeResult& result) {
    return formatPoints(result.points) + " / " + formatPoints(result.maxPoints);
}

TableLayout layoutOf(const std::vector<GradeResult>& results, const Totals& totals) {
    TableLayout layout;
    layout.uniform = !results.empty() && sameThresholds(results);
    layout.known = std::any_of(results.begin(), results.end(),
                               [](const GradeResult& result) { return result.maxFlipMean > 0.0; });
    for (const GradeResult& result : results) {
        if (quietCascade(totals, result)) continue;
        layout.labWidth = std::max(layout.labWidth, result.lab.size());
        layout.statusWidth = std::max(layout.statusWidth, std::string(statusName(result.status)).size());
        if (result.counted && collapsed(totals, result.lab)) {   // its one line says "(N cases)" and the lab's points
            layout.caseWidth = std::max<std::size_t>(layout.caseWidth, 10);
            layout.pointsWidth = std::max<std::size_t>(layout.pointsWidth, 7);
            continue;
        }
        layout.caseWidth = std::max(layout.caseWidth, caseLabel(result).size());
        layout.pointsWidth = std::max(layout.pointsWidth, pointsText(result).size());
    }
    if (layout.uniform && layout.known) {
        layout.pixelsLimit = "pass: <= " + percentText(results.front().maxBadFraction);
        layout.flipLimit = "pass: <= " + flipText(results.front().maxFlipMean);
    }
    layout.pixelsWidth = std::max(layout.pixelsWidth, layout.pixelsLimit.size());
    return layout;
}

void printHeader(std::ostream& out, const TableLayout& layout) {
    out << padded("lab", layout.labWidth) << "  " << padded("case", layout.caseWidth) << "  "
        << padded("status", layout.statusWidth) << "  " << padded("points", layout.pointsWidth) << "  "
        << padded("differing pixels", layout.pixelsWidth) << "  " << "FLIP mean\n";
    if (layout.uniform && layout.known)
        out << std::string(layout.rowStart(), ' ') << "  " << padded(layout.pixelsLimit, layout.pixelsWidth) << "  "
            << layout.flipLimit << "\n";
    std::size_t columns = layout.rowStart() + layout.pixelsWidth + layout.flipWidth + 2;
    out << std::string(std::max<std::size_t>(columns, 40), '-') << "\n";
}

// The one line of a lab whose every case is "not attempted", and where to start;
// under the first lab to start with (`withStub`), the stub its first case met.
void printCollapsedLab(std::ostream& out, const TableLayout& layout, const Totals& totals, const GradeResult& result,
                       bool withStub) {
    auto lab = std::find_if(totals.labs.begin(), totals.labs.end(),
                            [&](const LabTotals& entry) { return entry.lab == result.lab; });
    int count = lab->statuses.total();
    out << padded(result.lab, layout.labWidth) << "  "
        << padded("(" + std::to_string(count) + (count == 1 ? " case)" : " cases)"), layout.caseWidth) << "  "
        << padded(statusName(GradeStatus::NotAttempted), layout.statusWidth) << "  "
        << padded(formatPoints(lab->points) + " / " + formatPoints(lab->maxPoints), layout.pointsWidth);
    const std::string first = labToStartWith(result);
    const std::string stub = stubNamed(result.reason);
    if (first != result.lab) {
        // The stub where it fits; else on a line of its own, unless the lab
        // waited for has its own line in this report, which names its stub.
        const std::string waits = "  waits for lab " + first;
        const std::string which = stub.empty() ? "" : " (" + stub + " is a stub there)";
        const bool fits = layout.rowStart() + waits.size() + which.size() <= kLineWidth;
        out << waits << (fits ? which : "") << "\n";
        const bool shown = std::any_of(totals.labs.begin(), totals.labs.end(),
                                       [&](const LabTotals& entry) { return entry.lab == first; });
        if (!fits && !shown && !stub.empty())
            for (const std::string& line : wrapped(stub + " is a stub there", kLineWidth, layout.labWidth + 2,
                                                   std::min(layout.rowStart(), kLineWidth / 2)))
                out << line << "\n";
        return;
    }
    out << "  start with docs/labs/" << result.lab << ".md\n";
    // The stub on a line of its own under that text (or under the case column,
    // when the table is too wide for that).
    const std::string text = "first stub: " + stub;
    std::size_t column = layout.rowStart();
    if (column + text.size() > 100) column = layout.labWidth + 2;
    if (withStub && !stub.empty() && column + text.size() <= 100) out << std::string(column, ' ') << text << "\n";
}

// One case's row: its metrics, its verdict or its reason; then its hint.
void printCaseRow(std::ostream& out, const TableLayout& layout, const GradeResult& result) {
    std::string row = padded(result.lab, layout.labWidth) + "  " + padded(caseLabel(result), layout.caseWidth) + "  " +
                      padded(statusName(result.status), layout.statusWidth) + "  " +
                      padded(pointsText(result), layout.pointsWidth) + "  ";
    if (result.metrics) {
        std::string pixels = pixelsCell(result), flip = flipCell(result);
        if (!layout.uniform && layout.known) {
            pixels += " (<= " + percentText(result.maxBadFraction) + ")";
            flip += " (<= " + flipText(result.maxFlipMean) + ")";
        }
        row += padded(pixels, layout.pixelsWidth) + "  " + flip;
    } else if (result.propertyCheck && (result.status == GradeStatus::Passed || result.status == GradeStatus::Failed)) {
        // A property check has no picture: its verdict; what it measured is in the details when it fails.
        row += result.status == GradeStatus::Passed ? "property check: holds"
                                                    : "property check: does not hold (see the details below)";
    } else if (!result.reason.empty()) {
        // The reason in full where it fits, else in the details.
        bool fits = row.size() + result.reason.size() <= kLineWidth && result.reason.find('\n') == std::string::npos;
        row += fits ? result.reason : std::string("(see the details below)");
    }
    while (!row.empty() && row.back() == ' ') row.pop_back();
    out << row << (result.counted ? "" : "  (not counted)") << "\n";
    const std::size_t indent = layout.labWidth + 2;
    if (result.hasHint())
        for (const std::string& line : wrapped(hintLine(result), kLineWidth, indent + 6, indent)) out << line << "\n";
}

// A case that did not pass: its reason in full, where it differs, and its pictures.
void printCaseDetails(std::ostream& out, const GradeResult& result) {
    for (const std::string& line :
         wrapped(result.fullName() + ": " + statusName(result.status) + ": " + result.reason, kLineWidth, 6, 2))
        out << line << "\n";
    if (!result.difference.empty())
        for (const std::string& line : wrapped("where: " + result.difference, kLineWidth, 11, 4)) out << line << "\n";
    if (!result.renderedImage.empty() && result.status == GradeStatus::Failed)
        out << "    yours:     " << result.renderedImage.string() << "\n";
    if (!result.heatMapImage.empty()) out << "    heat map:  " << result.heatMapImage.string() << "\n";
    if (!result.referenceImage.empty() && result.status == GradeStatus::Failed)
        out << "    reference: " << result.referenceImage.string() << "\n";
}

// Details: only the cases that did not pass, and one entry per distinct error of a lab.
void printDetails(std::ostream& out, const TableLayout& layout, const std::vector<GradeResult>& results,
                  const Totals& totals) {
    bool headerPrinted = false;
    auto header = [&]() {
        if (!headerPrinted) out << "\ndetails (the cases that did not pass):\n";
        headerPrinted = true;
    };
    std::vector<ErrorGroup> errors;
    for (const GradeResult& result : results) {
        if (result.status == GradeStatus::Passed) continue;
        if ((result.counted && collapsed(totals, result.lab)) || quietCascade(totals, result)) continue;
        if (result.status == GradeStatus::Error) {
            const std::string output = lastLines(result.programOutput, kOutputLinesShown);
            auto group = std::find_if(errors.begin(), errors.end(), [&](const ErrorGroup& entry) {
                return entry.lab == result.lab && entry.reason == result.reason && entry.output == output;
            });
            if (group == errors.end()) group = errors.insert(errors.end(), ErrorGroup{result.lab, result.reason, output, {}});
            group->cases.push_back(caseLabel(result));
            continue;
        }
        if ((result.status == GradeStatus::NotAttempted || result.status == GradeStatus::NoReference) &&
            layout.rowStart() + result.reason.size() <= kLineWidth && result.reason.find('\n') == std::string::npos)
            continue;   // the row said it in full
        header();
        printCaseDetails(out, result);
    }
    for (const ErrorGroup& group : errors) {
        header();
        std::string cases;
        for (const std::string& name : group.cases) cases += (cases.empty() ? "" : ", ") + name;
        std::string who = group.cases.size() == 1 ? group.lab + "/" + cases
                                                  : group.lab + " (" + std::to_string(group.cases.size()) +
                                                        " cases: " + cases + ")";
        for (const std::string& line : wrapped(who + ": error: " + group.reason, kLineWidth, 6, 2))
            out << line << "\n";
        if (!group.output.empty()) out << "    the program's last output:\n" << group.output;
    }
}

// Missing references, the points per lab (and its cascade), the total, the lab
// to start with next (`next`, when some lab has nothing attempted) and the score line.
void printTotals(std::ostream& out, const TableLayout& layout, const Totals& totals, const std::string& next) {
    int missingReferences = totals.statuses[GradeStatus::NoReference];
    if (missingReferences > 0)
        out << "\n" << missingReferences << (missingReferences == 1 ? " case has" : " cases have")
            << " no reference image: run stoa-grade --update-references from a solutions build\n";
    out << "\n";
    for (const LabTotals& lab : totals.labs) {
        const bool cascadeSaysMore = lab.hasCascade && (lab.ownPoints > 0.0 || lab.cascadePoints > 0.0);
        if (lab.nothingAttempted() && !cascadeSaysMore) continue;   // its one line above has the points
        out << padded(lab.lab, layout.labWidth) << "  " << formatPoints(lab.points) << " / "
            << formatPoints(lab.maxPoints) << " points  (" << lab.statuses.describe() << ")\n";
        if (cascadeSaysMore)
            out << padded("", layout.labWidth) << "  with your earlier labs " << formatPoints(lab.ownPoints)
                << ", with their solutions " << formatPoints(lab.cascadePoints) << ": the higher counts\n";
    }
    if (totals.labs.size() > 1)
        out << padded("total", layout.labWidth) << "  " << formatPoints(totals.points) << " / "
            << formatPoints(totals.maxPoints) << " points  (" << totals.statuses.describe() << ")\n";
    if (!next.empty()) out << "next: lab " << next << ", docs/labs/" << next << ".md\n";
    out << "score: " << formatPoints(totals.points) << " / " << formatPoints(totals.maxPoints) << "\n";
}

} // namespace

void printReport(std::ostream& out, const std::vector<GradeResult>& results, const Totals& totals) {
    const TableLayout layout = layoutOf(results, totals);
    printHeader(out, layout);
    std::vector<std::string> collapsedShown;
    std::string next;   // the first lab to start with
    for (const GradeResult& result : results) {
        if (quietCascade(totals, result)) continue;
        if (!(result.counted && collapsed(totals, result.lab))) {
            printCaseRow(out, layout, result);
        } else if (std::find(collapsedShown.begin(), collapsedShown.end(), result.lab) == collapsedShown.end()) {
            collapsedShown.push_back(result.lab);
            const std::string start = labToStartWith(result);
            const bool first = next.empty() && start == result.lab;
            if (next.empty()) next = start;
            printCollapsedLab(out, layout, totals, result, first);
        }
    }
    printDetails(out, layout, results, totals);
    printTotals(out, layout, totals, next);
}

std::string hintLine(const GradeResult& result, std::size_t indent) {
    if (!result.hasHint()) return "";
    std::string line = std::string(indent, ' ') + "hint: looks like the known mistake '" + result.hintMistake + "'";
    if (result.hintDistance >= 0.0 && result.metrics && result.metrics->flipMean >= 0.0)
        line += " (FLIP mean " + flipText(result.hintDistance) + " from its picture, " +
                flipText(result.metrics->flipMean) + " from the reference)";
    line += ": " + result.hint;
    if (!result.hintDocs.empty()) line += " (read " + result.hintDocs + ")";
    return line;
}

std::vector<std::string> hints(const Totals& totals) {
    std::vector<std::string> lines;
    for (const LabTotals& lab : totals.labs)
        if (lab.nothingAttempted())
            lines.push_back("lab " + lab.lab + ": nothing attempted yet -- start with docs/labs/" + lab.lab + ".md");
    return lines;
}

} // namespace stoa::grader
