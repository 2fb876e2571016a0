#pragma once
// The outcome of grading one case: its status, the reason in one line, the
// points it earned, and where its images are.

#include <stoa/image/ImageCompare.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace stoa::grader {

enum class GradeStatus {
    Passed,         // the image matches the reference
    Failed,         // the image differs from the reference (a wrong answer)
    NotAttempted,   // the program exited 3: a stub threw NotImplemented
    Error,          // crash, timeout, nonzero exit, missing or unreadable image, wrong size
    NoReference,    // rendered, but there is no reference image to compare with
};

/// The figures of a comparison with the reference, without its per-pixel maps
/// (results of a whole class are kept in memory at once).
struct CompareMetrics {
    double badFraction = 1.0;   // fraction of pixels beyond the tolerance, in [0, 1]
    double meanError = 255.0;   // mean shift-tolerant difference, 0..255
    int maxError = 255;         // largest shift-tolerant difference, 0..255
    double flipMean = -1.0;     // mean LDR-FLIP error in [0, 1]; < 0 when not computed
};

/// The figures of `comparison`.
CompareMetrics metricsOf(const CompareResult& comparison);

/// Every status, in the order above.
inline constexpr GradeStatus kAllStatuses[] = {GradeStatus::Passed, GradeStatus::Failed, GradeStatus::NotAttempted,
                                               GradeStatus::Error, GradeStatus::NoReference};

/// "passed", "failed", "not attempted", "error", "no reference": the one
/// spelling of each status (reports, results.json tags, class summaries).
const char* statusName(GradeStatus status);
/// The status statusName() spells `name`; nothing for another word.
std::optional<GradeStatus> statusFromName(const std::string& name);

struct GradeResult {
    std::string lab;                       // "01_transforms"
    std::string caseName;                  // "orbit_front"
    GradeStatus status = GradeStatus::Error;
    std::string reason;                    // one line: the compare summary or why it is not graded
    double points = 0.0;                   // earned: maxPoints when passed, else 0
    double maxPoints = 0.0;
    Visibility visibility = Visibility::Visible;
    double seconds = 0.0;                  // wall-clock time of the render
    bool timedOut = false;                 // the lab program ran past its time limit and was killed
    bool busyWhenStopped = false;          // timedOut while computing: too slow, not waiting on anything
    std::string programOutput;             // the lab program's stdout+stderr, truncated to ~4 KB
    std::filesystem::path renderedImage;   // the student's image (empty when none was written)
    std::filesystem::path heatMapImage;    // written for failed cases of the right size
    std::filesystem::path referenceImage;
    std::optional<CompareMetrics> metrics; // set when the image was compared with the reference
    bool propertyCheck = false;            // a property check (cases.ini `check`): no picture, `reason` says why
    double maxBadFraction = 0.0;           // the case's pass thresholds (CompareOptions): share of
    double maxFlipMean = 0.0;              // differing pixels, FLIP mean
    std::string difference;                // a failed case: where the picture differs and how much
                                           // ("23% of the pixels, most in the top left; darker there")

    // A failed case whose image is much closer to a known mistake's (the lab's
    // mistake gallery) than to the reference, in a lab whose passed and failed
    // cases agree with that mistake, carries its hint (the rule: Hints.hpp).
    std::string hint;                      // the mistake's `hint:` text; empty when no mistake matches
    std::string hintDocs;                  // "docs/labs/02_shading.md#the-half-vector"; empty when none
    std::string hintMistake;               // the mistake's name, "no_half_vector"
    std::filesystem::path hintImage;       // the gallery's picture of this case for that mistake
    double hintDistance = -1.0;            // FLIP mean of the student's picture against it

    // Cascades (Cascade.hpp): a lab that uses earlier labs is graded twice where
    // solutions exist, with the student's own earlier labs and with their
    // solutions; the run with more points counts.
    bool cascade = false;                  // rendered by <bin>/cascade/labNN_name (earlier labs' solutions linked in)
    bool counted = true;                   // false: the lab's other run counts; the case adds nothing to the totals

    /// "01_transforms/orbit_front"; "05_shadows/sun [cascade]" for a cascade run
    std::string fullName() const { return lab + "/" + caseName + (cascade ? " [cascade]" : ""); }
    bool hasHint() const { return !hint.empty(); }
};

} // namespace stoa::grader
