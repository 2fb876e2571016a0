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
    gallery.add(jobs);
    return gallery;
}

void HintGallery::add(const std::vector<CaseJob>& jobs) {
    std::map<std::filesystem::path, std::vector<KnownMistake>> mistakesByFolder;
    for (const CaseJob& job : jobs) {
        if (m_images.count(job.reference)) continue;
        std::vector<GalleryImage>& images = m_images[job.reference];
        std::filesystem::path referenceDir = job.reference.parent_path();
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
            std::filesystem::path path = mistake.imageFor(job.spec.name);
            std::error_code error;
            if (!std::filesystem::is_regular_file(path, error)) continue;
            try {
                images.push_back(GalleryImage{mistake, Image::load(path)});
            } catch (const std::exception&) {
                // An image that does not decode gives no hint.
            }
        }
    }
}

const std::vector<GalleryImage>& HintGallery::imagesFor(const CaseJob& job) const {
    auto found = m_images.find(job.reference);
    return found == m_images.end() ? kNoImages : found->second;
}

std::size_t HintGallery::imageCount() const {
    std::size_t count = 0;
    for (const auto& [reference, images] : m_images) count += images.size();
    return count;
}

namespace {

using RuledOut = std::map<std::filesystem::path, std::vector<std::string>>;   // program -> mistake names

bool isRuledOut(const RuledOut& ruledOut, const std::filesystem::path& program, const std::string& mistake) {
    auto found = ruledOut.find(program);
    return found != ruledOut.end() && std::find(found->second.begin(), found->second.end(), mistake) != found->second.end();
}

// Rule (b), per program: the mistakes its statuses rule out need no picture compared.
RuledOut ruledOutByPattern(const std::vector<CaseOutcome>& outcomes, const HintGallery& gallery) {
    std::map<std::filesystem::path, std::vector<std::pair<std::string, GradeStatus>>> statuses;
    for (const CaseOutcome& outcome : outcomes)
        statuses[outcome.job.program].emplace_back(outcome.result.caseName, outcome.result.status);
    RuledOut ruledOut;
    for (const CaseOutcome& outcome : outcomes) {
        std::vector<std::string>& out = ruledOut[outcome.job.program];
        for (const GalleryImage& image : gallery.imagesFor(outcome.job))
            if (std::find(out.begin(), out.end(), image.mistake.name) == out.end() &&
                !patternAgrees(image.mistake.fails, statuses[outcome.job.program]))
                out.push_back(image.mistake.name);
    }
    return ruledOut;
}

// Rule (a): a mistake whose picture is not clearly closer on one of the
// program's failed cases is out for the whole program.
void ruleOutByPicture(const std::vector<CaseOutcome>& outcomes, const std::vector<std::size_t>& failed,
                      const std::vector<CaseDistances>& distances, const HintGallery& gallery, RuledOut& ruledOut) {
    for (std::size_t i : failed) {
        if (!distances[i].measured) continue;
        const std::vector<GalleryImage>& images = gallery.imagesFor(outcomes[i].job);
        std::vector<std::string>& out = ruledOut[outcomes[i].job.program];
        for (std::size_t k = 0; k < images.size(); ++k)
            if (std::find(out.begin(), out.end(), images[k].mistake.name) == out.end() &&
                !clearlyCloser(distances[i].toMistake[k], distances[i].toReference))
                out.push_back(images[k].mistake.name);
    }
}

// The closest mistake left for a failed case, as its hint.
void hintClosest(CaseOutcome& outcome, const CaseDistances& distances, const std::vector<GalleryImage>& images,
                 const RuledOut& ruledOut) {
    std::optional<std::size_t> best;
    for (std::size_t k = 0; k < images.size(); ++k) {
        if (isRuledOut(ruledOut, outcome.job.program, images[k].mistake.name)) continue;
        if (!best || ratio(distances.toMistake[k], distances.toReference) <
                         ratio(distances.toMistake[*best], distances.toReference))
            best = k;
    }
    if (!best) return;
    const KnownMistake& mistake = images[*best].mistake;
    GradeResult& result = outcome.result;
    result.hint = mistake.hint;
    result.hintDocs = docsPath(mistake.docs);
    result.hintMistake = mistake.name;
    result.hintImage = mistake.imageFor(outcome.job.spec.name);
    result.hintDistance = distances.toMistake[*best].flipMean;
}

} // namespace

void addHints(std::vector<CaseOutcome>& outcomes, const HintGallery& gallery, int parallelJobs) {
    for (CaseOutcome& outcome : outcomes) clearHint(outcome.result);
    RuledOut ruledOut = ruledOutByPattern(outcomes, gallery);

    // The pictures of every failed case against its gallery images.
    std::vector<CaseDistances> distances(outcomes.size());
    std::vector<std::size_t> failed;
    for (std::size_t i = 0; i < outcomes.size(); ++i)
        if (outcomes[i].result.status == GradeStatus::Failed && !gallery.imagesFor(outcomes[i].job).empty())
            failed.push_back(i);
    forEachInParallel(failed.size(), parallelJobs, [&](std::size_t k) {
        const CaseOutcome& outcome = outcomes[failed[k]];
        try {
            distances[failed[k]] = measure(outcome.result, outcome.job, gallery.imagesFor(outcome.job),
                                           ruledOut.at(outcome.job.program));
        } catch (const std::exception&) {
            distances[failed[k]] = CaseDistances{};   // an image that does not read: this case says nothing
        }
    });
    ruleOutByPicture(outcomes, failed, distances, gallery, ruledOut);
    for (std::size_t i : failed)
        if (distances[i].measured) hintClosest(outcomes[i], distances[i], gallery.imagesFor(outcomes[i].job), ruledOut);
}

void addHints(std::vector<CaseOutcome>& outcomes, int parallelJobs) {
    std::vector<CaseJob> jobs;
    for (const CaseOutcome& outcome : outcomes) jobs.push_back(outcome.job);
    addHints(outcomes, HintGallery::load(jobs), parallelJobs);
}

} // namespace stoa::grader
