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

// One failed case's distances to the gallery images of its case.
struct CaseDistances {
    bool measured = false;                     // the images were read and compared
    CompareMetrics toReference;
    std::vector<CompareMetrics> toMistake;     // per gallery image of the case; badFraction 1 when of another size
};

CaseDistances measure(const GradeResult& result, const CaseJob& job, const std::vector<GalleryImage>& images,
                      const std::vector<std::string>& ruledOut) {
    CaseDistances distances;
    if (result.status != GradeStatus::Failed || result.renderedImage.empty() || images.empty()) return distances;
    Image rendered = Image::load(result.renderedImage);
    distances.toReference = result.metrics ? *result.metrics
                                           : metricsOf(compareImages(rendered, Image::load(job.reference),
                                                                     job.spec.compare));
    distances.toMistake.resize(images.size());
    for (std::size_t k = 0; k < images.size(); ++k) {
        const Image& image = images[k].image;
        bool skip = std::find(ruledOut.begin(), ruledOut.end(), images[k].mistake.name) != ruledOut.end();
        if (skip || image.width() != rendered.width() || image.height() != rendered.height()) continue;
        distances.toMistake[k] = metricsOf(compareImages(rendered, image, job.spec.compare));
    }
    distances.measured = true;
    return distances;
}

double ratio(const CompareMetrics& toMistake, const CompareMetrics& toReference) {
    if (toMistake.flipMean >= 0.0 && toReference.flipMean > 0.0) return toMistake.flipMean / toReference.flipMean;
    if (toReference.badFraction > 0.0) return toMistake.badFraction / toReference.badFraction;
    return 1.0;
}

void clearHint(GradeResult& result) {
    result.hint.clear();
    result.hintDocs.clear();
    result.hintMistake.clear();
    result.hintImage.clear();
    result.hintDistance = -1.0;
}

} // namespace

bool isCloser(const CompareMetrics& a, const CompareMetrics& b) {
    if (a.flipMean >= 0.0 && b.flipMean >= 0.0 && a.flipMean != b.flipMean) return a.flipMean < b.flipMean;
    if (a.badFraction != b.badFraction) return a.badFraction < b.badFraction;
    return a.meanError < b.meanError;
}

bool clearlyCloser(const CompareMetrics& toMistake, const CompareMetrics& toReference) {
    if (toMistake.flipMean >= 0.0 && toReference.flipMean >= 0.0)
        return toReference.flipMean > 0.0 && toMistake.flipMean <= kHintMargin * toReference.flipMean;
    return toReference.badFraction > 0.0 && toMistake.badFraction <= kHintMargin * toReference.badFraction;
}

bool patternAgrees(const std::vector<std::string>& mistakeFails,
                   const std::vector<std::pair<std::string, GradeStatus>>& statuses) {
    for (const auto& [name, status] : statuses) {
        bool mistakeFailsIt = std::find(mistakeFails.begin(), mistakeFails.end(), name) != mistakeFails.end();
        if (mistakeFailsIt && status == GradeStatus::Passed) return false;   // it would have failed
    }
    return true;
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
        gallery.push_back(
            KnownMistake{entry.path().filename().string(), header.hint, header.docs, entry.path(), header.fails});
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
        if (!clearlyCloser(distance, referenceDistance ? *referenceDistance : best)) continue;
        if (!closest || isCloser(distance, best)) {
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
    for (std::size_t i = 0; i < count; ++i) clearHint(results[i]);

    // Rule (b) first, per program: the mistakes its statuses rule out need no picture compared.
    std::map<std::filesystem::path, std::vector<std::pair<std::string, GradeStatus>>> statuses;
    for (std::size_t i = 0; i < count; ++i)
        statuses[jobs[i].program].emplace_back(results[i].caseName, results[i].status);
    std::map<std::filesystem::path, std::vector<std::string>> ruledOut;   // program -> mistake names
    for (std::size_t i = 0; i < count; ++i)
        for (const GalleryImage& image : gallery.imagesFor(i)) {
            std::vector<std::string>& out = ruledOut[jobs[i].program];
            if (std::find(out.begin(), out.end(), image.mistake.name) == out.end() &&
                !patternAgrees(image.mistake.fails, statuses[jobs[i].program]))
                out.push_back(image.mistake.name);
        }

    // Rule (a): the pictures of every failed case against its gallery images.
    std::vector<CaseDistances> distances(count);
    std::vector<std::size_t> failed;
    for (std::size_t i = 0; i < count; ++i)
        if (results[i].status == GradeStatus::Failed && !gallery.imagesFor(i).empty()) failed.push_back(i);
    for (std::size_t i : failed) ruledOut[jobs[i].program];   // no insertion below, from several threads
    forEachInParallel(failed.size(), parallelJobs, [&](std::size_t k) {
        std::size_t i = failed[k];
        try {
            distances[i] = measure(results[i], jobs[i], gallery.imagesFor(i), ruledOut.at(jobs[i].program));
        } catch (const std::exception&) {
            distances[i] = CaseDistances{};   // an image that does not read: this case says nothing
        }
    });
    // A mistake whose picture is not clearly closer on one of its failed cases is out for the whole program.
    for (std::size_t i : failed) {
        if (!distances[i].measured) continue;
        const std::vector<GalleryImage>& images = gallery.imagesFor(i);
        for (std::size_t k = 0; k < images.size(); ++k) {
            std::vector<std::string>& out = ruledOut[jobs[i].program];
            if (std::find(out.begin(), out.end(), images[k].mistake.name) != out.end()) continue;
            if (!clearlyCloser(distances[i].toMistake[k], distances[i].toReference))
                out.push_back(images[k].mistake.name);
        }
    }

    for (std::size_t i : failed) {
        if (!distances[i].measured) continue;
        const std::vector<GalleryImage>& images = gallery.imagesFor(i);
        const std::vector<std::string>& out = ruledOut[jobs[i].program];
        std::optional<std::size_t> best;
        for (std::size_t k = 0; k < images.size(); ++k) {
            if (std::find(out.begin(), out.end(), images[k].mistake.name) != out.end()) continue;
            if (!best || ratio(distances[i].toMistake[k], distances[i].toReference) <
                             ratio(distances[i].toMistake[*best], distances[i].toReference))
                best = k;
        }
        if (!best) continue;
        const KnownMistake& mistake = images[*best].mistake;
        results[i].hint = mistake.hint;
        results[i].hintDocs = docsPath(mistake.docs);
        results[i].hintMistake = mistake.name;
        results[i].hintImage = mistake.imageFor(jobs[i].spec.name);
        results[i].hintDistance = distances[i].toMistake[*best].flipMean;
    }
}

void addHints(std::vector<GradeResult>& results, const std::vector<CaseJob>& jobs, int parallelJobs) {
    addHints(results, jobs, HintGallery::load(jobs), parallelJobs);
}

} // namespace stoa::grader
