#pragma once
// The outcome of grading one case: its status, the reason in one line, the
// points it earned, and where its images are.

#include <stoa/lab/CaseManifest.hpp>

#include <filesystem>
#include <string>

namespace stoa::grader {

enum class GradeStatus {
    Passed,         // the image matches the reference
    Failed,         // the image differs from the reference (a wrong answer)
    NotAttempted,   // the program exited 3: a stub threw NotImplemented
    Error,          // crash, timeout, nonzero exit, missing or unreadable image, wrong size
    NoReference,    // rendered, but there is no reference image to compare with
};

/// "passed", "failed", "not attempted", "error", "no reference".
const char* statusName(GradeStatus status);

struct GradeResult {
    std::string lab;                       // "01_transforms"
    std::string caseName;                  // "orbit_front"
    GradeStatus status = GradeStatus::Error;
    std::string reason;                    // one line: the compare summary or why it is not graded
    double points = 0.0;                   // earned: maxPoints when passed, else 0
    double maxPoints = 0.0;
    Visibility visibility = Visibility::Visible;
    double seconds = 0.0;                  // wall-clock time of the render
    std::string programOutput;             // the lab program's stdout+stderr, truncated to ~4 KB
    std::filesystem::path renderedImage;   // the student's image (empty when none was written)
    std::filesystem::path heatMapImage;    // written for failed cases of the right size
    std::filesystem::path referenceImage;

    /// "01_transforms/orbit_front"
    std::string fullName() const { return lab + "/" + caseName; }
};

} // namespace stoa::grader
