#pragma once
// Hints from the known-mistake gallery. A wrong hint is worse than none, so a
// failed case names a known mistake only when both hold:
//
//   (a) the picture: on every case the mistake fails (its gallery images) that
//       the student's program failed too, the student's picture is closer to the
//       mistake's picture than to the reference by a clear margin: its FLIP mean
//       against the mistake's picture is at most kHintMargin (one third) of its
//       FLIP mean against the reference;
//   (b) the pattern: no case the mistake fails (per its gallery) passed for the
//       student; one that did rules the mistake out. A case the student failed
//       that the mistake is not known to fail does not rule it out: the gallery
//       records only the cases a mistake fails (it is never rendered for the
//       others, and never for hidden cases), a student may have two mistakes,
//       and that case gets no hint from this mistake anyway -- the hint goes
//       only on the mistake's own cases, where (a) holds on every one of them.
//       Cases that were not graded, not attempted or errors say nothing either way.
//
// Among the mistakes that pass both, each case takes the one whose picture is
// closest. A failed case without a hint still says where its picture differs and
// how much (GradeResult::difference, from describeDifference()).
//
// A gallery entry's hint describes the symptom and the known causes with their
// files, so that it stays true for neighbours of the planted cause.
//
// The gallery lives next to the references (written by
// `stoa-grade --update-references` from a solutions build):
//
//   autograder/references/<lab>/<case>.png                          the reference
//   autograder/references/<lab>/mistakes/<mistake>/mistake.txt      hint:, docs:, fails:, file:
//   autograder/references/<lab>/mistakes/<mistake>/<case>.png       what the mistake renders
//
// It ships with the student release (it holds no solution code), so hints work
// where solutions/ is absent.

#include "CaseOutcome.hpp"
#include "CaseRunner.hpp"
#include "GradeResult.hpp"
#include "MistakeFile.hpp"

#include <stoa/image/Image.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stoa::grader {

/// The file in each mistake's gallery folder that carries its hint.
constexpr const char* kGalleryInfoFile = "mistake.txt";

/// One planted mistake as the gallery keeps it.
struct KnownMistake {
    std::string name;                  // "no_half_vector" (the folder's name)
    std::string hint;
    std::string docs;                  // "labs/02_shading.md#the-half-vector", as in the .mistake file
    std::filesystem::path folder;      // <referenceDir>/mistakes/<name>
    std::vector<std::string> fails;    // the cases it fails, which have gallery images (its info file's fails:)

    /// <folder>/<caseName>.png (it may not exist: a mistake renders only the cases it fails).
    std::filesystem::path imageFor(const std::string& caseName) const { return folder / (caseName + ".png"); }
};

/// How much closer to a mistake's picture than to the reference a student's
/// picture must be, as a ratio of FLIP means: rule (a) above.
constexpr double kHintMargin = 1.0 / 3.0;

/// True when `a` (a comparison's figures) is strictly closer than `b`: by the
/// FLIP mean when both have one (>= 0) and they differ, else by the fraction of
/// bad pixels, then by the mean error of the shift-tolerant gate.
bool isCloser(const CompareMetrics& a, const CompareMetrics& b);

/// Rule (a) for one case: `toMistake` (the student's picture against the
/// mistake's) is within kHintMargin of `toReference`, by FLIP mean when both
/// have one, else by the fraction of pixels beyond the tolerance.
bool clearlyCloser(const CompareMetrics& toMistake, const CompareMetrics& toReference);

/// Rule (b): whether the statuses of one program's cases (case name -> status)
/// agree with a mistake that fails `mistakeFails`.
bool patternAgrees(const std::vector<std::string>& mistakeFails,
                   const std::vector<std::pair<std::string, GradeStatus>>& statuses);

/// The gallery info file's text for `mistake`, parseable by parseMistakeHeader().
/// `cases` are the cases it has images for.
std::string galleryInfoText(const MistakeFile& mistake, const std::vector<std::string>& cases);

/// The known mistakes of the lab whose references are in `referenceDir`, sorted
/// by name; none when there is no gallery. Throws InputError for an info file
/// that does not parse.
std::vector<KnownMistake> loadGallery(const std::filesystem::path& referenceDir);

/// One gallery image of a case, with the mistake it shows.
struct GalleryImage {
    KnownMistake mistake;
    Image image;
};

/// The gallery images of every case of a run, read before any lab program runs,
/// so that no program can change or remove what its hints are chosen from. Kept
/// once per reference picture: a lab's own run and its cascade run share them.
class HintGallery {
public:
    /// Reads the gallery images of each job's case (from the gallery next to the
    /// job's reference). Never throws: a gallery whose info file does not parse,
    /// or an image that does not decode, gives no hints.
    static HintGallery load(const std::vector<CaseJob>& jobs);
    /// Reads those of `jobs` whose reference it has not read yet.
    void add(const std::vector<CaseJob>& jobs);

    /// The images for `job`'s case (none for a reference it has not read).
    const std::vector<GalleryImage>& imagesFor(const CaseJob& job) const;
    /// How many images it holds in all.
    std::size_t imageCount() const;

private:
    std::map<std::filesystem::path, std::vector<GalleryImage>> m_images;   // by the job's reference
};

/// The index in `gallery` of the mistake `rendered` is closest to, when that
/// one is clearly closer than `reference` (clearlyCloser(), rule (a) for one
/// case); nullopt otherwise (also for an empty gallery). Images of another size
/// than `rendered` are skipped. `referenceDistance` is the rendered-vs-reference
/// distance when known.
std::optional<std::size_t> closestMistake(const Image& rendered, const Image& reference,
                                          const std::vector<GalleryImage>& gallery, const CompareOptions& options,
                                          const std::optional<CompareMetrics>& referenceDistance = std::nullopt);

/// "docs/labs/01_transforms.md#the-view-matrix" for "labs/01_transforms.md#the-view-matrix"
/// ("" for ""; a leading "docs/" or "/" is not doubled).
std::string docsPath(const std::string& docs);

/// Sets hint, hintDocs, hintMistake, hintImage and hintDistance on every failed
/// result that meets rules (a) and (b) above for a gallery mistake. The results
/// of the same program are judged together (rule (b)); `gallery` was loaded from
/// the outcomes' jobs before grading. The reference distance is the one grading
/// measured; the reference is read only when a result lacks it. Never throws.
/// Works on `parallelJobs` cases at once.
void addHints(std::vector<CaseOutcome>& outcomes, const HintGallery& gallery, int parallelJobs = 1);

/// The same with the gallery read now.
void addHints(std::vector<CaseOutcome>& outcomes, int parallelJobs = 1);

} // namespace stoa::grader
