#include "MistakeGallery.hpp"

#include "Hints.hpp"
#include "ReferenceUpdate.hpp"
#include "ReportFile.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <algorithm>
#include <deque>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace stoa::grader {

namespace {

bool contains(const std::vector<std::string>& list, const std::string& word) {
    return std::find(list.begin(), list.end(), word) != list.end();
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    if (file) text << file.rdbuf();
    return text.str();
}

// Rewrites mistake.txt for the images now in `folder` and the property checks
// the mistake fails (`checks`: the lab's check cases; they have no image), and
// removes images of cases the mistake no longer lists; an empty folder goes altogether.
void finishMistakeFolder(const std::filesystem::path& folder, const MistakeFile& mistake,
                         const std::set<std::string>& checks, GallerySummary& summary, std::ostream& out) {
    std::error_code error;
    std::vector<std::string> cases;
    for (const std::string& name : mistake.fails)
        if (checks.count(name) > 0 || std::filesystem::is_regular_file(folder / (name + ".png"), error))
            cases.push_back(name);
    if (std::filesystem::is_directory(folder, error)) {
        for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
            std::string stem = entry.path().stem().string();
            if (entry.path().extension() != ".png" || contains(mistake.fails, stem)) continue;
            std::filesystem::remove(entry.path(), error);
            ++summary.removed;
            out << mistake.lab << "/" << stem << " [mistake " << mistake.name
                << "]: removed (no longer in its fails: line)\n";
        }
    }
    if (cases.empty()) {
        if (std::filesystem::remove_all(folder, error) > 0) ++summary.removed;
        return;
    }
    std::filesystem::create_directories(folder, error);
    std::filesystem::path info = folder / kGalleryInfoFile;
    std::string text = galleryInfoText(mistake, cases);
    if (readFile(info) != text) writeReportFile(info, text, "the mistake gallery's info file");
}

// Removes the gallery folders of mistakes that have no .mistake file any more.
void pruneDeletedMistakes(const PlannedLab& lab, const Environment& env, GallerySummary& summary,
                          std::ostream& out) {
    std::vector<std::string> names;
    for (const MistakeFile& mistake : loadMistakes(env.sourceDir / "solutions" / lab.lab))
        names.push_back(mistake.name);
    std::filesystem::path folder = referenceImagePath(env.sourceDir, lab.lab, "any").parent_path() / "mistakes";
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) return;
    std::vector<std::filesystem::path> stale;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (entry.is_directory() && !contains(names, entry.path().filename().string())) stale.push_back(entry.path());
    for (const std::filesystem::path& path : stale) {
        std::filesystem::remove_all(path, error);
        ++summary.removed;
        out << lab.lab << ": removed the gallery of deleted mistake " << path.filename().string() << "\n";
    }
}

} // namespace

std::vector<GalleryJob> galleryJobs(const std::vector<PlannedLab>& labs, const Environment& env,
                                    const std::filesystem::path& workDir, std::vector<std::string>& notes) {
    std::vector<GalleryJob> jobs;
    for (const PlannedLab& lab : labs) {
        for (const MistakeFile& mistake : loadMistakes(env.sourceDir / "solutions" / lab.lab)) {
            std::filesystem::path program = mistakeProgram(env.binDir, lab.lab, mistake.name);
            if (!isExecutable(program)) {
                notes.push_back("note: mistake " + lab.lab + "." + mistake.name + " is not built (no program " +
                                program.string() + "); its gallery images are left as they are");
                continue;
            }
            std::filesystem::path folder = workDir / "mistakes" / (lab.lab + "." + mistake.name);
            for (const CaseJob& job : caseJobs(lab, program, env.sourceDir, folder))
                // Property checks draw no picture: the gallery has images of picture cases only.
                if (contains(mistake.fails, job.spec.name) && job.spec.check.empty())
                    jobs.push_back(GalleryJob{mistake, job});
        }
    }
    return jobs;
}

std::filesystem::path galleryImagePath(const GalleryJob& job) {
    return job.job.reference.parent_path() / "mistakes" / job.mistake.name / (job.job.spec.name + ".png");
}

GallerySummary updateGallery(const std::vector<GalleryJob>& jobs, const std::vector<RenderOutcome>& renders,
                             const std::vector<PlannedLab>& labs, const Environment& env, bool pruneDeleted,
                             std::ostream& out) {
    GallerySummary summary;
    std::map<std::filesystem::path, const MistakeFile*> folders;
    for (std::size_t i = 0; i < jobs.size() && i < renders.size(); ++i) {
        const GalleryJob& gallery = jobs[i];
        const CaseJob& job = gallery.job;
        std::filesystem::path target = galleryImagePath(gallery);
        folders[target.parent_path()] = &gallery.mistake;
        out << job.lab << "/" << job.spec.name << " [mistake " << gallery.mistake.name << "]: ";
        if (!renders[i].rendered) {
            ++summary.problems;
            out << statusName(renders[i].status) << ": " << renders[i].reason << "\n";
            continue;
        }
        Image reference;
        try {
            reference = Image::load(job.reference);
        } catch (const InputError& error) {
            ++summary.problems;
            out << "no reference to compare with (" << error.message() << ")\n";
            continue;
        }
        if (compareImages(renders[i].image, reference, job.spec.compare).passed) {
            std::error_code error;
            if (std::filesystem::remove(target, error)) ++summary.removed;
            out << "matches the reference, so no gallery image (take the case out of its fails: line)\n";
            continue;
        }
        bool ok = false;
        std::string line = writeOrKeepImage(target, job.spec.compare, renders[i], ok);
        if (ok) {
            ++summary.images;
            if (line.rfind("unchanged", 0) != 0) ++summary.written;
        } else {
            ++summary.problems;
        }
        out << line << "\n";
    }
    // The property checks of each lab, and the mistakes that fail one: their gallery
    // entries list those checks (a mistake that fails checks only has no image at all).
    std::map<std::string, std::set<std::string>> checks;
    std::deque<MistakeFile> checkMistakes;
    for (const PlannedLab& lab : labs) {
        for (const CaseSpec& spec : lab.manifest.cases)
            if (!spec.check.empty()) checks[lab.lab].insert(spec.name);
        if (checks[lab.lab].empty()) continue;
        for (MistakeFile& mistake : loadMistakes(env.sourceDir / "solutions" / lab.lab)) {
            const bool failsACheck = std::any_of(mistake.fails.begin(), mistake.fails.end(),
                                                 [&](const std::string& name) { return checks[lab.lab].count(name) > 0; });
            if (!failsACheck || !isExecutable(mistakeProgram(env.binDir, lab.lab, mistake.name))) continue;
            std::filesystem::path folder = referenceImagePath(env.sourceDir, lab.lab, "any").parent_path() / "mistakes" /
                                           mistake.name;
            if (folders.count(folder) == 0) {
                checkMistakes.push_back(std::move(mistake));
                folders[folder] = &checkMistakes.back();
            }
        }
    }
    for (const auto& [folder, mistake] : folders)
        finishMistakeFolder(folder, *mistake, checks[mistake->lab], summary, out);
    if (pruneDeleted)
        for (const PlannedLab& lab : labs) pruneDeletedMistakes(lab, env, summary, out);
    return summary;
}

} // namespace stoa::grader
