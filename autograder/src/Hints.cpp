#include "Hints.hpp"

#include "Grader.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>

namespace stoa::grader {

namespace {

std::string readText(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path.string(), 0, "cannot read the mistake gallery's info file");
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

const std::vector<GalleryImage> kNoImages;

// Hints for one failed case; leaves the result as it is when anything is missing.
void addHint(GradeResult& result, const CaseJob& job, const std::vector<GalleryImage>& images) {
    if (result.status != GradeStatus::Failed || result.renderedImage.empty() || images.empty()) return;
    Image rendered = Image::load(result.renderedImage);
    Image reference;
    if (!result.metrics) reference = Image::load(job.reference);
    std::optional<std::size_t> closest = closestMistake(rendered, reference, images, job.spec.compare, result.metrics);
    if (!closest) return;
    const KnownMistake& mistake = images[*closest].mistake;
    result.hint = mistake.hint;
    result.hintDocs = docsPath(mistake.docs);
    result.hintMistake = mistake.name;
}

} // namespace

bool isCloser(const CompareMetrics& a, const CompareMetrics& b) {
    if (a.flipMean >= 0.0 && b.flipMean >= 0.0 && a.flipMean != b.flipMean) return a.flipMean < b.flipMean;
    if (a.badFraction != b.badFraction) return a.badFraction < b.badFraction;
    return a.meanError < b.meanError;
}

std::string galleryInfoText(const MistakeFile& mistake, const std::vector<std::string>& cases) {
    std::string fails;
    for (const std::string& name : cases) fails += (fails.empty() ? "" : " ") + name;
    std::string text = "# Written by stoa-grade --update-references from solutions/" + mistake.lab + "/mistakes/" +
                       mistake.name + ".mistake; edit that file, not this one.\n";
    text += "hint: " + mistake.hint + "\n";
    if (!mistake.docs.empty()) text += "docs: " + mistake.docs + "\n";
    text += "fails: " + fails + "\n";
    text += "file: " + mistake.file + "\n";
    return text;
}

std::vector<KnownMistake> loadGallery(const std::filesystem::path& referenceDir) {
    std::vector<KnownMistake> gallery;
    std::filesystem::path folder = referenceDir / "mistakes";
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) return gallery;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        std::filesystem::path info = entry.path() / kGalleryInfoFile;
        if (!entry.is_directory() || !std::filesystem::is_regular_file(info)) continue;
        MistakeFile header = parseMistakeHeader(readText(info), info.string());
        gallery.push_back(KnownMistake{entry.path().filename().string(), header.hint, header.docs, entry.path()});
    }
    std::sort(gallery.begin(), gallery.end(),
              [](const KnownMistake& a, const KnownMistake& b) { return a.name < b.name; });
    return gallery;
}

std::optional<std::size_t> closestMistake(const Image& rendered, const Image& reference,
                                          const std::vector<GalleryImage>& gallery, const CompareOptions& options,
                                          const std::optional<CompareMetrics>& referenceDistance) {
    CompareMetrics best = referenceDistance ? *referenceDistance : metricsOf(compareImages(rendered, reference, options));
    std::optional<std::size_t> closest;
    for (std::size_t i = 0; i < gallery.size(); ++i) {
        const Image& image = gallery[i].image;
        if (image.width() != rendered.width() || image.height() != rendered.height()) continue;
        CompareMetrics distance = metricsOf(compareImages(rendered, image, options));
        if (isCloser(distance, best)) {
            best = distance;
            closest = i;
        }
    }
    return closest;
}

std::string docsPath(const std::string& docs) {
    if (docs.empty()) return "";
    std::string path = docs;
    while (!path.empty() && path[0] == '/') path.erase(0, 1);
    return path.rfind("docs/", 0) == 0 ? path : "docs/" + path;
}

HintGallery HintGallery::load(const std::vector<CaseJob>& jobs) {
    HintGallery gallery;
    gallery.m_images.resize(jobs.size());
    std::map<std::filesystem::path, std::vector<KnownMistake>> mistakesByFolder;
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        std::filesystem::path referenceDir = jobs[i].reference.parent_path();
        auto found = mistakesByFolder.find(referenceDir);
        if (found == mistakesByFolder.end()) {
            std::vector<KnownMistake> mistakes;
            try {
                mistakes = loadGallery(referenceDir);
            } catch (const std::exception&) {
                // An info file that does not parse: no hints for this lab, never a failed grading.
            }
            found = mistakesByFolder.emplace(referenceDir, std::move(mistakes)).first;
        }
        for (const KnownMistake& mistake : found->second) {
            std::filesystem::path path = mistake.imageFor(jobs[i].spec.name);
            std::error_code error;
            if (!std::filesystem::is_regular_file(path, error)) continue;
            try {
                gallery.m_images[i].push_back(GalleryImage{mistake, Image::load(path)});
            } catch (const std::exception&) {
                // An image that does not decode gives no hint.
            }
        }
    }
    return gallery;
}

const std::vector<GalleryImage>& HintGallery::imagesFor(std::size_t jobIndex) const {
    return jobIndex < m_images.size() ? m_images[jobIndex] : kNoImages;
}

std::size_t HintGallery::imageCount() const {
    std::size_t count = 0;
    for (const std::vector<GalleryImage>& images : m_images) count += images.size();
    return count;
}

void addHints(std::vector<GradeResult>& results, const std::vector<CaseJob>& jobs, const HintGallery& gallery,
              int parallelJobs) {
    std::size_t count = std::min(results.size(), jobs.size());
    std::vector<std::size_t> failed;
    for (std::size_t i = 0; i < count; ++i)
        if (results[i].status == GradeStatus::Failed && !gallery.imagesFor(i).empty()) failed.push_back(i);
    forEachInParallel(failed.size(), parallelJobs, [&](std::size_t k) {
        std::size_t i = failed[k];
        try {
            addHint(results[i], jobs[i], gallery.imagesFor(i));
        } catch (const std::exception&) {
            results[i].hint.clear();
            results[i].hintDocs.clear();
            results[i].hintMistake.clear();
        }
    });
}

void addHints(std::vector<GradeResult>& results, const std::vector<CaseJob>& jobs, int parallelJobs) {
    addHints(results, jobs, HintGallery::load(jobs), parallelJobs);
}

} // namespace stoa::grader
