#include "Report.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace stoa::grader {

namespace {

constexpr std::size_t kReasonColumnWidth = 64;
constexpr int kOutputLinesShown = 12;

// The case column: a cascade run's cases are marked.
std::string caseLabel(const GradeResult& result) {
    return result.cascade ? result.caseName + " [cascade]" : result.caseName;
}

std::string padded(const std::string& text, std::size_t width) {
    return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

std::string shortened(const std::string& text, std::size_t width) {
    return text.size() <= width ? text : text.substr(0, width - 3) + "...";
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

} // namespace

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

void printReport(std::ostream& out, const std::vector<GradeResult>& results, const Totals& totals) {
    std::size_t labWidth = 3, caseWidth = 4, statusWidth = 6, reasonWidth = 5;
    for (const GradeResult& result : results) {
        labWidth = std::max(labWidth, result.lab.size());
        caseWidth = std::max(caseWidth, caseLabel(result).size());
        statusWidth = std::max(statusWidth, std::string(statusName(result.status)).size());
        reasonWidth = std::max(reasonWidth, std::min(result.reason.size(), kReasonColumnWidth));
    }
    out << padded("lab", labWidth) << "  " << padded("case", caseWidth) << "  " << padded("status", statusWidth)
        << "  " << padded("error", reasonWidth) << "  points\n";
    out << std::string(labWidth + caseWidth + statusWidth + reasonWidth + 8 + 6, '-') << "\n";
    for (const GradeResult& result : results) {
        out << padded(result.lab, labWidth) << "  " << padded(caseLabel(result), caseWidth) << "  "
            << padded(statusName(result.status), statusWidth) << "  "
            << padded(shortened(result.reason, kReasonColumnWidth), reasonWidth) << "  "
            << formatPoints(result.points) << " / " << formatPoints(result.maxPoints)
            << (result.counted ? "" : " (not counted)") << "\n";
        if (result.hasHint()) out << hintLine(result, labWidth + 2) << "\n";
    }

    bool headerPrinted = false;
    for (const GradeResult& result : results) {
        bool interesting = result.status == GradeStatus::Failed || result.status == GradeStatus::Error ||
                           (result.status != GradeStatus::NoReference && result.reason.size() > kReasonColumnWidth);
        if (!interesting) continue;
        if (!headerPrinted) out << "\ndetails:\n";
        headerPrinted = true;
        out << "  " << result.fullName() << ": " << statusName(result.status) << ": " << result.reason << "\n";
        if (!result.renderedImage.empty() && result.status == GradeStatus::Failed)
            out << "    yours:     " << result.renderedImage.string() << "\n";
        if (!result.heatMapImage.empty()) out << "    heat map:  " << result.heatMapImage.string() << "\n";
        if (!result.referenceImage.empty() && result.status == GradeStatus::Failed)
            out << "    reference: " << result.referenceImage.string() << "\n";
        if (result.status == GradeStatus::Error && !result.programOutput.empty())
            out << "    the program's last output:\n" << lastLines(result.programOutput, kOutputLinesShown);
    }

    int missingReferences = totals.statuses[GradeStatus::NoReference];
    if (missingReferences > 0)
        out << "\n" << missingReferences << (missingReferences == 1 ? " case has" : " cases have")
            << " no reference image: run stoa-grade --update-references from a solutions build\n";

    out << "\n";
    for (const LabTotals& lab : totals.labs)
    {
        out << padded(lab.lab, labWidth) << "  " << formatPoints(lab.points) << " / " << formatPoints(lab.maxPoints)
            << " points  (" << lab.statuses.describe() << ")\n";
        if (lab.hasCascade)
            out << padded("", labWidth) << "  with your earlier labs " << formatPoints(lab.ownPoints)
                << ", with their solutions " << formatPoints(lab.cascadePoints) << ": the higher counts\n";
    }
    if (totals.labs.size() > 1)
        out << padded("total", labWidth) << "  " << formatPoints(totals.points) << " / "
            << formatPoints(totals.maxPoints) << " points  (" << totals.statuses.describe() << ")\n";
    out << "score: " << formatPoints(totals.points) << " / " << formatPoints(totals.maxPoints) << "\n";
}

std::string hintLine(const GradeResult& result, std::size_t indent) {
    if (!result.hasHint()) return "";
    std::string line = std::string(indent, ' ') + "hint: looks like the known mistake '" + result.hintMistake +
                       "': " + result.hint;
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
