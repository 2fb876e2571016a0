// Comparing the students' own code with SIM, lab by lab. Declared in Similarity.hpp.

#include "Similarity.hpp"

#include "BatchGradeSubmissions.hpp"
#include "ChildProcess.hpp"
#include "ReportFile.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <regex>
#include <sstream>

namespace stoa::grader {

const char* const kSimInstallHint =
    "the similarity tester (sim_c, sim_text) is not installed: apt-get install similarity-tester (Debian, Ubuntu; "
    ".ci/install-deps.sh installs it)";

namespace {

constexpr std::uintmax_t kMaxFileBytes = 1u << 20;   // a larger student file is left out of the comparison

// A line as givenLines() compares it: without whitespace, and without the '{'
// that ends it (where a function's opening brace goes is layout).
std::string comparable(const std::string& line) {
    std::string kept;
    for (char c : line)
        if (!std::isspace(static_cast<unsigned char>(c))) kept += c;
    if (kept.size() > 1 && kept.back() == '{') kept.pop_back();
    return kept;
}

std::vector<std::string> readLines(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A lab's file in a labs/ tree: NN_name/student/FILE, or NN_name/FILE as releases before the student/ folders had it.
std::filesystem::path labFile(const std::filesystem::path& labsDir, const std::string& lab, const std::string& file) {
    std::error_code error;
    for (const std::filesystem::path& candidate : {labsDir / lab / "student" / file, labsDir / lab / file})
        if (std::filesystem::is_regular_file(candidate, error) && !std::filesystem::is_symlink(candidate, error))
            return candidate;
    return {};
}

ProcessLimits simLimits(const std::filesystem::path& labDir, double timeoutSeconds) {
    ProcessLimits limits = defaultLimits(timeoutSeconds);
    limits.files = systemFileAccess();
    limits.files.writable.push_back(labDir);
    limits.outputLimitBytes = 16384;
    limits.maxProcesses = 4;
    limits.fileSizeBytes = 1ull << 30;   // the -p output of a large class
    return limits;
}

// Writes each student's text of `lab` into `labDir` and returns them; files the stub lacks count whole.
std::vector<StudentText> writeTexts(const std::map<std::string, std::filesystem::path>& submissions,
                                    const std::filesystem::path& sourceDir, const std::string& lab,
                                    const std::vector<std::string>& files, const std::filesystem::path& labDir) {
    std::map<std::string, std::vector<std::string>> stubs;
    for (const std::string& file : files) {
        std::filesystem::path stub = labFile(sourceDir / "labs", lab, file);
        if (!stub.empty()) stubs[file] = readLines(stub);
    }
    std::vector<StudentText> texts;
    int index = 0;
    for (const auto& [student, labsDir] : submissions) {
        StudentText text;
        text.student = student;
        char name[32];
        std::snprintf(name, sizeof name, "s%04d.txt", ++index);
        text.simName = name;
        for (const std::string& file : files) {
            std::filesystem::path path = labFile(labsDir, lab, file);
            std::error_code error;
            if (path.empty() || std::filesystem::file_size(path, error) > kMaxFileBytes || error) continue;
            std::vector<std::string> lines = readLines(path);
            std::vector<bool> given = givenLines(stubs[file], lines);
            for (std::size_t i = 0; i < lines.size(); ++i) {
                text.lines.push_back(lines[i]);
                text.given.push_back(given[i]);
                text.origin.emplace_back(file, static_cast<int>(i + 1));
            }
        }
        std::string simText;
        for (std::size_t i = 0; i < text.lines.size(); ++i) simText += (text.given[i] ? "" : text.lines[i]) + "\n";
        std::ofstream(labDir / text.simName, std::ios::binary) << simText;
        texts.push_back(std::move(text));
    }
    return texts;
}

// The pairs of `kept` ranked by the share of their code they have in common.
std::vector<SimilarPair> rankPairs(const std::vector<const StudentText*>& kept,
                                   const std::map<std::pair<std::string, std::string>, int>& percentages) {
    auto percentOf = [&](const std::string& a, const std::string& b) {
        auto found = percentages.find({a, b});
        return found == percentages.end() ? 0 : found->second;
    };
    std::vector<SimilarPair> pairs;
    for (std::size_t i = 0; i < kept.size(); ++i)
        for (std::size_t j = i + 1; j < kept.size(); ++j) {
            const StudentText& a = *kept[i];
            const StudentText& b = *kept[j];
            SimilarPair pair;
            pair.a = a.student;
            pair.b = b.student;
            pair.percentA = percentOf(a.simName, b.simName);
            pair.percentB = percentOf(b.simName, a.simName);
            if (pair.percentA == 0 && pair.percentB == 0) continue;
            pair.score = (double(pair.percentA) * a.tokens + double(pair.percentB) * b.tokens) /
                         std::max(1, a.tokens + b.tokens);
            pairs.push_back(pair);
        }
    std::stable_sort(pairs.begin(), pairs.end(), [](const SimilarPair& x, const SimilarPair& y) {
        return x.score > y.score;
    });
    return pairs;
}

LabSimilarity compareLab(const std::map<std::string, std::filesystem::path>& submissions,
                         const std::filesystem::path& sourceDir, const std::string& lab,
                         const std::filesystem::path& workDir, const SimilarityOptions& options) {
    LabSimilarity result;
    result.lab = lab;
    result.files = studentFilesOf(sourceDir, lab);
    result.tool = simToolFor(result.files);
    std::filesystem::path tool = findSimTool(result.tool);
    if (tool.empty()) {
        result.error = kSimInstallHint;
        return result;
    }
    std::filesystem::path labDir = std::filesystem::absolute(workDir / lab);
    std::filesystem::remove_all(labDir);
    std::filesystem::create_directories(labDir);
    std::vector<StudentText> texts = writeTexts(submissions, sourceDir, lab, result.files, labDir);

    // sim_text counts words, not tokens: it keeps its own minimum run (8 words).
    const std::string run = std::to_string(result.tool == "sim_c" ? options.minimumRun : 8);
    std::vector<std::string> argv = {tool.string(), "-e", "-p", "-s", "-a", "-t", "1", "-r", run, "-o", "percentages.txt"};
    for (const StudentText& text : texts) argv.push_back(text.simName);
    ProcessOutcome outcome = runProcess(argv, labDir, simLimits(labDir, options.timeoutSeconds));
    if (!outcome.exitedWith(0)) {
        result.error = result.tool + " " + outcome.describe() + ": " + outcome.lastOutputLine();
        return result;
    }
    std::string output = readText(labDir / "percentages.txt");
    std::map<std::string, int> tokens = parseTokenCounts(output);
    std::vector<const StudentText*> kept;
    for (StudentText& text : texts) {
        text.tokens = tokens.count(text.simName) ? tokens[text.simName] : 0;
        if (text.tokens < options.minimumTokens) result.leftOut.push_back(text.student);
        else kept.push_back(&text);
    }
    result.pairsCompared = static_cast<int>(kept.size() * (kept.size() - (kept.empty() ? 0 : 1)) / 2);
    result.pairs = rankPairs(kept, parsePercentages(output));

    std::map<std::string, const StudentText*> byStudent;
    for (const StudentText& text : texts) byStudent[text.student] = &text;
    const int shown = std::min(static_cast<int>(result.pairs.size()), options.pairsShown);
    for (int i = 0; i < shown; ++i) {
        SimilarPair& pair = result.pairs[static_cast<std::size_t>(i)];
        const std::string& a = byStudent[pair.a]->simName;
        const std::string& b = byStudent[pair.b]->simName;
        ProcessOutcome runs = runProcess({tool.string(), "-e", "-s", "-n", "-r", run, "-o", "runs.txt", a, b}, labDir,
                                         simLimits(labDir, options.timeoutSeconds));
        if (runs.exitedWith(0)) pair.runs = parseRuns(readText(labDir / "runs.txt"), a, b);
    }
    for (StudentText& text : texts) result.texts[text.student] = std::move(text);
    return result;
}

} // namespace

std::vector<bool> givenLines(const std::vector<std::string>& stub, const std::vector<std::string>& student) {
    std::vector<std::string> a;
    std::vector<std::string> b;
    std::vector<std::size_t> where;   // b's index -> student's line
    for (const std::string& line : stub)
        if (std::string kept = comparable(line); !kept.empty()) a.push_back(kept);
    for (std::size_t i = 0; i < student.size(); ++i)
        if (std::string kept = comparable(student[i]); !kept.empty()) {
            b.push_back(kept);
            where.push_back(i);
        }
    // The longest common subsequence, by the classic table (files are small),
    // read back from the end: a line the stub has more than once ('}') goes to
    // the student's last match, the closing brace of the function.
    const std::size_t n = a.size();
    const std::size_t m = b.size();
    std::vector<std::vector<int>> length(n + 1, std::vector<int>(m + 1, 0));   // of a[0, i) and b[0, j)
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j)
            length[i][j] = a[i - 1] == b[j - 1] ? length[i - 1][j - 1] + 1 : std::max(length[i - 1][j], length[i][j - 1]);
    std::vector<bool> given(student.size(), false);
    for (std::size_t i = n, j = m; i > 0 && j > 0;) {
        if (a[i - 1] == b[j - 1]) {
            given[where[j - 1]] = true;
            --i;
            --j;
        } else if (length[i - 1][j] >= length[i][j - 1]) {
            --i;
        } else {
            --j;
        }
    }
    // A '{' on a line of its own after a given line is that line's brace.
    for (std::size_t k = 1; k < where.size(); ++k)
        if (b[k] == "{" && given[where[k - 1]]) given[where[k]] = true;
    return given;
}

std::vector<std::string> studentFilesOf(const std::filesystem::path& sourceDir, const std::string& lab) {
    std::filesystem::path cmake = sourceDir / "labs" / lab / "CMakeLists.txt";
    std::istringstream words(readText(cmake));
    std::vector<std::string> files;
    bool taking = false;
    for (std::string word; words >> word;) {
        if (word.rfind("stoa_add_lab(", 0) == 0) word = word.substr(13);
        bool closes = !word.empty() && word.back() == ')';
        if (closes) word.pop_back();
        if (word == "STUDENT_FILES") taking = true;
        else if (word == "NAME" || word == "APP_SOURCES" || word == "USES") taking = false;
        else if (taking && !word.empty()) files.push_back(word);
        if (closes) taking = false;
    }
    if (files.empty()) throw InputError(cmake.string(), 0, "stoa_add_lab() lists no STUDENT_FILES");
    return files;
}

std::string simToolFor(const std::vector<std::string>& files) {
    static const char* const cLike[] = {".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".glsl",
                                        ".vert", ".frag", ".geom", ".comp", ".tesc", ".tese"};
    for (const std::string& file : files) {
        std::string extension = std::filesystem::path(file).extension().string();
        if (std::find(std::begin(cLike), std::end(cLike), extension) == std::end(cLike)) return "sim_text";
    }
    return "sim_c";
}

std::map<std::pair<std::string, std::string>, int> parsePercentages(const std::string& output) {
    static const std::regex line(R"(^(\S+) consists for (\d+) % of (\S+) material\s*$)");
    std::map<std::pair<std::string, std::string>, int> percentages;
    std::istringstream lines(output);
    std::smatch match;
    for (std::string text; std::getline(lines, text);)
        if (std::regex_match(text, match, line)) percentages[{match[1], match[3]}] = std::stoi(match[2]);
    return percentages;
}

std::map<std::string, int> parseTokenCounts(const std::string& output) {
    static const std::regex line(R"(^File (\S+): (\d+) (?:tokens?|words?), \d+ lines?\s*$)");   // sim_text counts words
    std::map<std::string, int> tokens;
    std::istringstream lines(output);
    std::smatch match;
    for (std::string text; std::getline(lines, text);)
        if (std::regex_match(text, match, line)) tokens[match[1]] = std::stoi(match[2]);
    return tokens;
}

std::vector<SharedRun> parseRuns(const std::string& output, const std::string& fileA, const std::string& fileB) {
    static const std::regex line(R"(^(\S+): line (\d+)-(\d+)\s*\|\s*(\S+): line (\d+)-(\d+)\s*\[(\d+)\]\s*$)");
    std::vector<SharedRun> runs;
    std::istringstream lines(output);
    std::smatch match;
    for (std::string text; std::getline(lines, text);) {
        if (!std::regex_match(text, match, line)) continue;
        SharedRun run;
        int first[2] = {std::stoi(match[2]), std::stoi(match[5])};
        int last[2] = {std::stoi(match[3]), std::stoi(match[6])};
        run.tokens = std::stoi(match[7]);
        if (match[1] == fileA && match[4] == fileB) {
            run.firstA = first[0], run.lastA = last[0], run.firstB = first[1], run.lastB = last[1];
        } else if (match[1] == fileB && match[4] == fileA) {
            run.firstA = first[1], run.lastA = last[1], run.firstB = first[0], run.lastB = last[0];
        } else {
            continue;
        }
        runs.push_back(run);
    }
    std::sort(runs.begin(), runs.end(), [](const SharedRun& x, const SharedRun& y) { return x.firstA < y.firstA; });
    return runs;
}

std::filesystem::path findSimTool(const std::string& tool) { return findOnPath(tool); }

std::vector<LabSimilarity> compareSubmissions(const std::map<std::string, std::filesystem::path>& submissions,
                                              const std::filesystem::path& sourceDir,
                                              const std::vector<std::string>& labs, const std::filesystem::path& workDir,
                                              const SimilarityOptions& options) {
    std::vector<LabSimilarity> results;
    for (const std::string& lab : labs) {
        try {
            results.push_back(compareLab(submissions, sourceDir, lab, workDir, options));
        } catch (const std::exception& error) {
            LabSimilarity failed;
            failed.lab = lab;
            failed.error = error.what();
            results.push_back(failed);
        }
    }
    return results;
}

int writeSimilarityReport(const std::map<std::string, std::filesystem::path>& submissions,
                          const std::filesystem::path& sourceDir, const std::vector<std::string>& labs,
                          const std::filesystem::path& outDir, const SimilarityOptions& options, std::ostream& out,
                          std::ostream& err) {
    if (findSimTool("sim_c").empty() && findSimTool("sim_text").empty()) {
        err << "stoa-grade-class: no similarity report: " << kSimInstallHint << "\n";
        return 1;
    }
    std::vector<LabSimilarity> results = compareSubmissions(submissions, sourceDir, labs, outDir / ".similarity", options);
    for (const LabSimilarity& lab : results)
        if (!lab.error.empty()) err << "stoa-grade-class: similarity of " << lab.lab << ": " << lab.error << "\n";
    writeReportFile(outDir / "similarity.json", similarityJson(results), "the similarity figures");
    writeReportFile(outDir / "similarity.html", similarityHtml(results, options), "the similarity report");
    out << "wrote " << (outDir / "similarity.html").string() << " and similarity.json (" << submissions.size()
        << " submissions, " << labs.size() << (labs.size() == 1 ? " lab" : " labs") << ")" << std::endl;
    return 0;
}

} // namespace stoa::grader
