#pragma once
// Adds grade results up per lab and overall, and prints them as the terminal
// table a student reads after `stoa-grade`.

#include "GradeResult.hpp"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace stoa::grader {

constexpr int kStatusCount = 5;

struct StatusCounts {
    std::array<int, kStatusCount> counts{};   // indexed by GradeStatus

    void add(GradeStatus status) { ++counts[static_cast<int>(status)]; }
    int operator[](GradeStatus status) const { return counts[static_cast<int>(status)]; }
    int total() const;
    /// "2 passed, 1 failed, 3 not attempted" (statuses with a zero count left out).
    std::string describe() const;
};

struct LabTotals {
    std::string lab;
    double points = 0.0;
    double maxPoints = 0.0;
    StatusCounts statuses;          // of the counted cases
    // A lab graded twice (Cascade.hpp): the points of each run; `points` is the higher.
    bool hasCascade = false;
    double ownPoints = 0.0;         // with the student's own earlier labs
    double cascadePoints = 0.0;     // with the earlier labs' solutions

    /// True when the lab has cases and every one of them is "not attempted".
    bool nothingAttempted() const;
};

struct Totals {
    std::vector<LabTotals> labs;   // in the order the results first name them
    double points = 0.0;
    double maxPoints = 0.0;
    StatusCounts statuses;
};

/// Sums points and counts statuses per lab and overall; results that are not
/// `counted` (the other run of a cascade counts) only add to ownPoints/cascadePoints.
Totals summarize(const std::vector<GradeResult>& results);

/// True when there is at least one result and every result has `status`.
bool allHaveStatus(const std::vector<GradeResult>& results, GradeStatus status);

/// Points as a person writes them: "10", "2.5", "0.25".
std::string formatPoints(double points);

/// The table (lab, case, status, points, the share of differing pixels and the
/// FLIP mean with their pass thresholds, or the reason where nothing was
/// compared; a wrapped hint under a case that looks like a known mistake; one
/// line for a lab where nothing was attempted), the details of the cases that did
/// not pass (full reason, where the picture differs, image paths; an error that
/// several cases of a lab share, with the end of the program's output, once),
/// the totals per lab and overall, and the final line "score: X / Y". Lines are
/// wrapped at word boundaries to 100 columns (a long path stays whole).
void printReport(std::ostream& out, const std::vector<GradeResult>& results, const Totals& totals);

/// "23.4%", "0.20%", "0.005%", "0%": a share of pixels as the report prints it.
std::string percentText(double fraction);
/// "0.213", "0": a FLIP mean as the report prints it.
std::string flipText(double flipMean);

/// `text` cut at spaces into lines of at most `width` columns (a longer word
/// stays whole); the first line starts with `firstIndent` spaces, the others
/// with `indent`.
std::vector<std::string> wrapped(const std::string& text, std::size_t width, std::size_t indent,
                                 std::size_t firstIndent);

/// The line printed under a case that carries a known-mistake hint:
/// "<indent>hint: looks like the known mistake 'no_half_vector' (FLIP mean 0.004
/// from its picture, 0.087 from the reference): The specular term ... (read
/// docs/labs/02_shading.md#the-half-vector)"; "" without a hint. Unwrapped.
std::string hintLine(const GradeResult& result, std::size_t indent = 0);

/// One line per lab where nothing was attempted yet, pointing at its docs page:
/// "lab 01_transforms: nothing attempted yet -- start with docs/labs/01_transforms.md".
std::vector<std::string> hints(const Totals& totals);

} // namespace stoa::grader
