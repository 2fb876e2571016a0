#pragma once
// Which submissions look alike: `stoa-grade-class --similarity` runs Debian's
// similarity tester (SIM: sim_c for C++ and GLSL, sim_text for other files;
// package similarity-tester) over the students' own code, lab by lab, and
// writes <out>/similarity.html (the ranked pairs with their shared runs side by
// side) and <out>/similarity.json.
//
// Given code never counts: each student file is aligned line by line with its
// stub (labs/NN_name/student/FILE), and the lines the stub has, in the stub's
// order, are blanked before SIM reads the file (sim's "/" separator would not
// do it: old files are still matched between two new ones). SIM compares
// tokens, so renamed identifiers, other layout and comments change nothing, and
// each pair is compared on its own (-e), so reordered functions are found too.
//
// Short functions whose correct solutions are alike are expected: the page
// ranks, it does not accuse, and says so.

#include <filesystem>
#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace stoa::grader {

struct SimilarityOptions {
    int minimumRun = 24;        // sim_c's -r: the tokens a shared run needs at least (SIM's own default);
                                // sim_text keeps its default of 8 words
    int pairsShown = 10;        // per lab, the pairs whose shared runs are shown side by side
    int pairsListed = 40;       // per lab, the pairs in the ranking table
    int minimumTokens = 30;     // a student's code of a lab with fewer tokens of their own is left out
    double timeoutSeconds = 600.0;   // one sim run
};

/// One student's own code of one lab: the lab's student files one after the
/// other, given lines blank.
struct StudentText {
    std::string student;
    std::string simName;                          // the file SIM reads, "s0003.c", in the lab's work folder
    std::vector<std::string> lines;               // as the student wrote them, given lines included
    std::vector<bool> given;                      // per line: the stub has it (blanked for SIM)
    std::vector<std::pair<std::string, int>> origin;   // per line: the student file and its line there
    int tokens = 0;                               // as SIM counted them
};

/// A run of tokens two students share: lines of each one's text (1-based, inclusive).
struct SharedRun {
    int firstA = 0, lastA = 0;
    int firstB = 0, lastB = 0;
    int tokens = 0;
};

struct SimilarPair {
    std::string a, b;          // students
    int percentA = 0;          // how much of a's own code is also in b's (SIM's -p)
    int percentB = 0;
    double score = 0.0;        // the shared share of both: (percentA * tokensA + percentB * tokensB) / (tokensA + tokensB)
    std::vector<SharedRun> runs;   // only for the pairs shown side by side
};

struct LabSimilarity {
    std::string lab;
    std::string tool;                             // "sim_c" or "sim_text"
    std::vector<std::string> files;               // the lab's student files
    std::map<std::string, StudentText> texts;     // by student
    std::vector<std::string> leftOut;             // students with too little code of their own
    std::vector<SimilarPair> pairs;               // best first
    int pairsCompared = 0;
    std::string error;                            // why this lab was not compared
};

/// Per line of `student`: whether it is given code, i.e. in a longest common
/// subsequence of the non-blank lines of `stub` and `student`, compared without
/// whitespace and without a '{' that ends the line; a '{' alone on the line
/// after a given line is given too (another brace style). Blank lines never are.
std::vector<bool> givenLines(const std::vector<std::string>& stub, const std::vector<std::string>& student);

/// The student files of a lab: the STUDENT_FILES of stoa_add_lab() in
/// <sourceDir>/labs/<lab>/CMakeLists.txt. Throws InputError naming the file.
std::vector<std::string> studentFilesOf(const std::filesystem::path& sourceDir, const std::string& lab);

/// "sim_c" when every file is C, C++ or GLSL, else "sim_text".
std::string simToolFor(const std::vector<std::string>& files);

/// SIM's -p lines "A consists for N % of B material", as (A, B) -> N.
std::map<std::pair<std::string, std::string>, int> parsePercentages(const std::string& output);

/// SIM's "File A: N tokens, M lines" lines (sim_text: "N words"), as A -> N.
std::map<std::string, int> parseTokenCounts(const std::string& output);

/// SIM's -n lines "A: line 14-71 | B: line 12-69 [671]" between `fileA` and
/// `fileB` (either order), as runs from A's side.
std::vector<SharedRun> parseRuns(const std::string& output, const std::string& fileA, const std::string& fileB);

/// Compares the students' code of each lab. `submissions` maps each student to
/// their labs/ folder (a file is looked for at NN_name/student/FILE, then
/// NN_name/FILE; a missing one is left out). The texts SIM reads go to
/// `workDir`/<lab>/. A lab SIM cannot compare carries its error.
std::vector<LabSimilarity> compareSubmissions(const std::map<std::string, std::filesystem::path>& submissions,
                                              const std::filesystem::path& sourceDir,
                                              const std::vector<std::string>& labs, const std::filesystem::path& workDir,
                                              const SimilarityOptions& options);

/// similarity.html (SimilarityHtml.cpp).
std::string similarityHtml(const std::vector<LabSimilarity>& labs, const SimilarityOptions& options);

/// similarity.json: per lab, the ranked pairs with their percentages and score.
std::string similarityJson(const std::vector<LabSimilarity>& labs);

/// Where sim_c is, or empty, with the line to say when it is not installed.
std::filesystem::path findSimTool(const std::string& tool);
extern const char* const kSimInstallHint;

/// --similarity: compares, writes <outDir>/similarity.html and similarity.json,
/// says what it wrote on `out`, problems on `err`. Returns 0 when written, 1
/// when SIM is missing.
int writeSimilarityReport(const std::map<std::string, std::filesystem::path>& submissions,
                          const std::filesystem::path& sourceDir, const std::vector<std::string>& labs,
                          const std::filesystem::path& outDir, const SimilarityOptions& options, std::ostream& out,
                          std::ostream& err);

} // namespace stoa::grader
