// The class's figures: score distributions, each case across the class, the
// mistakes hints named, what to teach again; class.json; --report-from.
// Declared in ClassReport.hpp.

#include "ClassReport.hpp"

#include "GradeResult.hpp"
#include "JsonWriter.hpp"
#include "ReportFile.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace stoa::grader {

namespace {

constexpr std::size_t kTeachingPoints = 12;   // the first screen's list

int binOf(double points, double maxPoints) {
    if (!(maxPoints > 0.0)) return 0;
    if (points >= maxPoints - 1e-9) return ScoreDistribution::kBins - 1;
    int bin = static_cast<int>(std::floor(points / maxPoints * 10.0 + 1e-9));
    return std::clamp(bin, 0, ScoreDistribution::kBins - 2);
}

void countCase(CaseSummary& summary, const std::string& status) {
    if (status == statusName(GradeStatus::Passed)) ++summary.passed;
    else if (status == statusName(GradeStatus::Failed)) ++summary.failed;
    else if (status == statusName(GradeStatus::NotAttempted)) ++summary.notAttempted;
    else ++summary.error;
}

// Each case of `lab` across the class, the mistakes its hints named, and the
// students whose lab did not compile, timed out or was not attempted.
LabSummary summarizeLab(const LabCases& lab, const std::vector<StudentRecord>& students) {
    LabSummary summary;
    summary.lab = lab.lab;
    std::vector<std::string> order = lab.order;
    std::map<std::string, CaseSummary> cases;
    std::map<std::string, MistakeSummary> mistakes;
    std::vector<double> points;
    double maxPoints = lab.maxPoints;
    for (const StudentRecord& student : students) {
        auto found = student.labs.find(lab.lab);
        if (found == student.labs.end()) {
            points.push_back(0.0);
            continue;
        }
        const LabRecord& record = found->second;
        points.push_back(record.points);
        maxPoints = std::max(maxPoints, record.maxPoints);
        if (record.doesNotCompile) summary.notCompiled.push_back({student.student, record.compileError});
        if (record.notAttempted()) summary.notAttempted.push_back(student.student);
        std::vector<std::string> late = record.timedOutCases();
        if (!late.empty()) {
            std::string list;
            for (const std::string& name : late) list += (list.empty() ? "" : ", ") + name;
            summary.timedOut.push_back({student.student, list});
        }
        for (const CaseRecord& result : record.cases) {
            if (!cases.count(result.name) && std::find(order.begin(), order.end(), result.name) == order.end())
                order.push_back(result.name);
            countCase(cases[result.name], result.status);
            if (result.hintMistake.empty()) continue;
            MistakeSummary& mistake = mistakes[result.hintMistake];
            mistake.name = result.hintMistake;
            if (mistake.hint.empty()) mistake.hint = result.hint;
            if (mistake.docs.empty()) mistake.docs = result.hintDocs;
            if (std::find(mistake.students.begin(), mistake.students.end(), student.student) == mistake.students.end())
                mistake.students.push_back(student.student);
            if (std::find(mistake.cases.begin(), mistake.cases.end(), result.name) == mistake.cases.end())
                mistake.cases.push_back(result.name);
        }
    }
    summary.scores = distributionOf(points, maxPoints);
    const int classSize = static_cast<int>(students.size());
    for (const std::string& name : order) {
        // A case of the manifests that no student's results have: a hidden case
        // a package without --with-hidden did not grade.
        if (!cases.count(name)) continue;
        CaseSummary caseSummary = cases[name];
        caseSummary.name = name;
        auto description = lab.descriptions.find(name);
        if (description != lab.descriptions.end()) caseSummary.description = description->second;
        caseSummary.propertyCheck = lab.checks.count(name) > 0;
        caseSummary.missing = classSize - caseSummary.passed - caseSummary.failed - caseSummary.notAttempted -
                              caseSummary.error;
        summary.cases.push_back(caseSummary);
    }
    std::stable_sort(summary.cases.begin(), summary.cases.end(),
                     [](const CaseSummary& a, const CaseSummary& b) { return a.passed < b.passed; });
    for (auto& entry : mistakes) {
        std::sort(entry.second.students.begin(), entry.second.students.end());
        summary.mistakes.push_back(entry.second);
    }
    std::stable_sort(summary.mistakes.begin(), summary.mistakes.end(),
                     [](const MistakeSummary& a, const MistakeSummary& b) { return a.students.size() > b.students.size(); });
    return summary;
}

// What to teach again, most students first: each gallery mistake a hint named,
// each picture case students got wrong (failed, not merely unattempted) in a
// lab where no hint named their mistake (a named one says it better), each
// property check that failed, each lab that did not compile for some.
std::vector<TeachingPoint> teachingPoints(const std::vector<LabSummary>& labs, const std::vector<StudentRecord>& students) {
    std::vector<TeachingPoint> points;
    for (const LabSummary& lab : labs) {
        for (const MistakeSummary& mistake : lab.mistakes)
            points.push_back({"mistake", lab.lab, mistake.name, mistake.hint, mistake.docs, mistake.students});
        for (const CaseSummary& summary : lab.cases) {
            if (summary.failed == 0) continue;
            TeachingPoint point{summary.propertyCheck ? "check" : "case", lab.lab, summary.name, summary.description,
                                "", {}};
            for (const StudentRecord& student : students) {
                auto found = student.labs.find(lab.lab);
                if (found == student.labs.end()) continue;
                const std::vector<CaseRecord>& cases = found->second.cases;
                // A hint on any case of the lab explains the student's other wrong
                // pictures there too (a hint needs the failures to agree with its
                // mistake, Hints.hpp, and hidden cases get none); a property check
                // tests a requirement of its own.
                if (!summary.propertyCheck &&
                    std::any_of(cases.begin(), cases.end(), [](const CaseRecord& c) { return !c.hintMistake.empty(); }))
                    continue;
                for (const CaseRecord& result : cases)
                    if (result.name == summary.name && result.status == statusName(GradeStatus::Failed))
                        point.students.push_back(student.student);
            }
            if (!point.students.empty()) points.push_back(point);
        }
        if (!lab.notCompiled.empty()) {
            TeachingPoint point{"compile", lab.lab, "does not compile", lab.notCompiled.front().detail, "", {}};
            for (const StudentProblem& problem : lab.notCompiled) point.students.push_back(problem.student);
            points.push_back(point);
        }
    }
    // A named mistake says more than the case it shows in: on a tie it comes first.
    auto rank = [](const TeachingPoint& point) { return point.kind == "mistake" ? 0 : point.kind == "check" ? 1 : 2; };
    std::stable_sort(points.begin(), points.end(), [&](const TeachingPoint& a, const TeachingPoint& b) {
        if (a.students.size() != b.students.size()) return a.students.size() > b.students.size();
        return rank(a) < rank(b);
    });
    if (points.size() > kTeachingPoints) points.resize(kTeachingPoints);
    return points;
}

void writeDistribution(JsonWriter& json, const ScoreDistribution& scores) {
    json.key("max_points").value(scores.maxPoints);
    json.key("mean").value(scores.mean);
    json.key("median").value(scores.median);
    json.key("histogram").beginArray();
    for (int bin = 0; bin < ScoreDistribution::kBins; ++bin) {
        json.beginObject();
        json.key("from_percent").value(bin * 10);
        json.key("to_percent").value(bin == ScoreDistribution::kBins - 1 ? 100 : bin * 10 + 10);
        json.key("count").value(scores.bins[static_cast<std::size_t>(bin)]);
        json.endObject();
    }
    json.endArray();
}

void writeStudentList(JsonWriter& json, const std::vector<std::string>& students) {
    json.beginArray();
    for (const std::string& student : students) json.value(student);
    json.endArray();
}

void writeProblems(JsonWriter& json, const char* key, const char* detailKey, const std::vector<StudentProblem>& problems) {
    json.key(key).beginArray();
    for (const StudentProblem& problem : problems)
        json.beginObject().key("student").value(problem.student).key(detailKey).value(problem.detail).endObject();
    json.endArray();
}

void writeLab(JsonWriter& json, const LabSummary& lab, int classSize) {
    json.beginObject();
    json.key("lab").value(lab.lab);
    writeDistribution(json, lab.scores);
    json.key("cases").beginArray();
    for (const CaseSummary& summary : lab.cases) {
        json.beginObject();
        json.key("name").value(summary.name);
        json.key("property_check").value(summary.propertyCheck);
        json.key("passed").value(summary.passed);
        json.key("failed").value(summary.failed);
        json.key("not_attempted").value(summary.notAttempted);
        json.key("error").value(summary.error);
        json.key("no_result").value(summary.missing);
        json.key("pass_rate").value(summary.passRate(classSize));
        json.endObject();
    }
    json.endArray();
    json.key("mistakes").beginArray();
    for (const MistakeSummary& mistake : lab.mistakes) {
        json.beginObject().key("name").value(mistake.name).key("hint").value(mistake.hint);
        json.key("docs").value(mistake.docs).key("students");
        writeStudentList(json, mistake.students);
        json.endObject();
    }
    json.endArray();
    writeProblems(json, "not_compiled", "first_error", lab.notCompiled);
    writeProblems(json, "timed_out", "cases", lab.timedOut);
    json.key("not_attempted");
    writeStudentList(json, lab.notAttempted);
    json.endObject();
}

} // namespace

ScoreDistribution distributionOf(const std::vector<double>& points, double maxPoints) {
    ScoreDistribution scores;
    scores.maxPoints = maxPoints;
    if (points.empty()) return scores;
    double sum = 0.0;
    for (double value : points) {
        sum += value;
        ++scores.bins[static_cast<std::size_t>(binOf(value, maxPoints))];
    }
    scores.mean = sum / static_cast<double>(points.size());
    std::vector<double> sorted = points;
    std::sort(sorted.begin(), sorted.end());
    std::size_t middle = sorted.size() / 2;
    scores.median = sorted.size() % 2 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2.0;
    return scores;
}

ClassSummary summarizeClass(std::vector<StudentRecord> students, std::vector<LabCases> labs, const std::string& source) {
    ClassSummary summary;
    summary.source = source;
    std::set<std::string> known;
    for (const LabCases& lab : labs) known.insert(lab.lab);
    std::set<std::string> extra;   // labs only the results name
    for (const StudentRecord& student : students)
        for (const auto& entry : student.labs)
            if (!known.count(entry.first)) extra.insert(entry.first);
    for (const std::string& lab : extra) labs.push_back(LabCases{lab, 0.0, {}, {}, {}});

    std::vector<double> totals;
    double maxTotal = 0.0;
    for (const LabCases& lab : labs) summary.labs.push_back(summarizeLab(lab, students));
    for (const LabSummary& lab : summary.labs) maxTotal += lab.scores.maxPoints;
    for (const StudentRecord& student : students) {
        totals.push_back(student.points);
        maxTotal = std::max(maxTotal, student.maxPoints);
        if (student.labs.empty() || (student.status != "graded" && student.status != "partly built" &&
                                     student.status != "build failed"))
            summary.notGraded.push_back({student.student, student.status + (student.note.empty() ? "" : ": " + student.note)});
    }
    summary.overall = distributionOf(totals, maxTotal);
    summary.teachAgain = teachingPoints(summary.labs, students);
    summary.students = std::move(students);
    return summary;
}

std::string classJson(const ClassSummary& summary) {
    const int classSize = static_cast<int>(summary.students.size());
    JsonWriter json;
    json.beginObject();
    json.key("source").value(summary.source);
    json.key("students").value(classSize);
    json.key("overall").beginObject();
    writeDistribution(json, summary.overall);
    json.endObject();
    json.key("labs").beginArray();
    for (const LabSummary& lab : summary.labs) writeLab(json, lab, classSize);
    json.endArray();
    json.key("teach_again").beginArray();
    for (const TeachingPoint& point : summary.teachAgain) {
        json.beginObject().key("kind").value(point.kind).key("lab").value(point.lab).key("name").value(point.name);
        json.key("text").value(point.text).key("students");
        writeStudentList(json, point.students);
        json.endObject();
    }
    json.endArray();
    json.key("scores").beginArray();
    for (const StudentRecord& student : summary.students) {
        json.beginObject().key("student").value(student.student).key("status").value(student.status);
        json.key("total").value(student.points).key("max").value(student.maxPoints);
        json.key("labs").beginObject();
        for (const LabSummary& lab : summary.labs) {
            auto found = student.labs.find(lab.lab);
            json.key(lab.lab).value(found == student.labs.end() ? 0.0 : found->second.points);
        }
        json.endObject().endObject();
    }
    json.endArray();
    writeProblems(json, "not_graded", "why", summary.notGraded);
    json.key("unreadable");
    writeStudentList(json, summary.unreadable);
    json.endObject();
    return json.text() + "\n";
}

void writeClassReport(const std::filesystem::path& outDir, const ClassSummary& summary) {
    writeReportFile(outDir / "class.json", classJson(summary), "the class report's figures");
    writeReportFile(outDir / "class.html", classHtml(summary), "the class report");
}

int runReportFrom(const std::filesystem::path& folder, const std::filesystem::path& outDir,
                  const std::filesystem::path& sourceDir, std::ostream& out, std::ostream& err) {
    std::vector<std::string> unreadable;
    std::vector<StudentRecord> students = readResultsFolder(folder, unreadable);
    for (const std::string& why : unreadable) err << "stoa-grade-class: left out " << why << "\n";
    if (students.empty()) {
        err << "stoa-grade-class: no results.json in " << folder.string() << " could be read\n";
        return 1;
    }
    std::vector<LabCases> labs;
    std::set<std::string> named;
    for (const StudentRecord& student : students)
        for (const auto& entry : student.labs) named.insert(entry.first);
    for (const std::string& lab : named) {
        try {
            labs.push_back(readLabCases(sourceDir, lab));
            // The results' own maximum: a Gradescope package without --with-hidden
            // grades no hidden case.
            labs.back().maxPoints = 0.0;
        } catch (const std::exception& error) {   // a broken manifest: the results still tell the cases
            err << "stoa-grade-class: " << error.what() << "\n";
            labs.push_back(LabCases{lab, 0.0, {}, {}, {}});
        }
    }
    ClassSummary summary = summarizeClass(std::move(students), labs, folder.string());
    summary.unreadable = unreadable;
    writeClassReport(outDir, summary);
    out << "wrote " << (outDir / "class.html").string() << " and class.json (" << summary.students.size()
        << " students" << (unreadable.empty() ? "" : ", " + std::to_string(unreadable.size()) + " files left out")
        << ")\n";
    return 0;
}

} // namespace stoa::grader
