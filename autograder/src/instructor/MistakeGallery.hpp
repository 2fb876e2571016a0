#pragma once
// The known-mistake gallery, written by `stoa-grade --update-references` next
// to the references it compares against (layout in Hints.hpp): for every planted
// mistake whose program is built (<bin>/mistakes/<lab>.<mistake>/), each case
// of its `fails:` line that it really fails against the reference is rendered to
//   autograder/references/<lab>/mistakes/<mistake>/<case>.png
// with its hint and docs in mistake.txt beside the images. Like references, an
// image within the case's tolerance of the one already there is kept as is.

#include "CaseRunner.hpp"
#include "LabPlan.hpp"
#include "MistakeFile.hpp"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace stoa::grader {

struct GalleryJob {
    MistakeFile mistake;
    CaseJob job;   // job.reference is the case's reference; the gallery image goes beside it
};

/// One job per built mistake of the planned labs and per selected case its
/// `fails:` line names, rendered under <workDir>/mistakes/<lab>.<mistake>/.
/// A mistake whose program is not built adds a line to `notes`. Throws
/// InputError for a .mistake file that does not parse.
std::vector<GalleryJob> galleryJobs(const std::vector<PlannedLab>& labs, const Environment& env,
                                    const std::filesystem::path& workDir, std::vector<std::string>& notes);

/// <dir of reference>/mistakes/<mistake>/<case>.png
std::filesystem::path galleryImagePath(const GalleryJob& job);

struct GallerySummary {
    int images = 0;     // gallery images now in place (new, changed or unchanged)
    int written = 0;    // of those, new or changed
    int removed = 0;    // stale images and folders of deleted mistakes
    int problems = 0;   // renders that failed, or images that could not be written
};

/// Once the references are up to date: writes or keeps each gallery image (only
/// where the mistake fails the case against the reference), rewrites each
/// mistake's mistake.txt, and removes images the mistakes no longer produce.
/// With `pruneDeleted` (every case of the labs was rendered), folders of
/// mistakes that no longer exist go too. Prints one line per image to `out`.
/// `renders[i]` is the outcome of `jobs[i]`.
GallerySummary updateGallery(const std::vector<GalleryJob>& jobs, const std::vector<RenderOutcome>& renders,
                             const std::vector<PlannedLab>& labs, const Environment& env, bool pruneDeleted,
                             std::ostream& out);

} // namespace stoa::grader
