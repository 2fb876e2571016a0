#include "LabCatalog.hpp"

#include "GradeOptions.hpp"

#include <algorithm>
#include <cctype>

#include <unistd.h>

namespace stoa::grader {

namespace {

bool isLabFolderName(const std::string& name) {
    return name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
           std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '_';
}

bool allDigits(const std::string& text) {
    return !text.empty() && std::all_of(text.begin(), text.end(),
                                        [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

bool matches(const std::string& lab, const std::string& request) {
    if (lab == request) return true;
    if (allDigits(request)) return request.size() <= 3 && std::stoi(request) == std::stoi(lab.substr(0, 2));
    return lab.substr(3) == request;
}

std::string labList(const std::vector<LabEntry>& labs) {
    if (labs.empty()) return "(none: no labs/NN_name/cases.ini found)";
    std::string list;
    for (const LabEntry& entry : labs) list += (list.empty() ? "" : ", ") + entry.lab;
    return list;
}

} // namespace

std::vector<LabEntry> findLabs(const std::filesystem::path& sourceDir) {
    std::vector<LabEntry> labs;
    std::filesystem::path labsDir = sourceDir / "labs";
    std::error_code error;
    if (!std::filesystem::is_directory(labsDir, error)) return labs;
    for (const auto& entry : std::filesystem::directory_iterator(labsDir)) {
        std::string name = entry.path().filename().string();
        std::filesystem::path manifest = entry.path() / "cases.ini";
        if (isLabFolderName(name) && std::filesystem::is_regular_file(manifest, error))
            labs.push_back(LabEntry{name, manifest});
    }
    std::sort(labs.begin(), labs.end(), [](const LabEntry& a, const LabEntry& b) { return a.lab < b.lab; });
    return labs;
}

std::vector<LabEntry> selectLabs(const std::vector<LabEntry>& labs, const std::vector<std::string>& requested) {
    if (requested.empty()) return labs;
    std::vector<bool> chosen(labs.size(), false);
    for (const std::string& request : requested) {
        bool found = false;
        for (std::size_t i = 0; i < labs.size(); ++i)
            if (matches(labs[i].lab, request)) chosen[i] = found = true;
        if (!found) throw UsageError("unknown lab '" + request + "'; the labs are: " + labList(labs));
    }
    std::vector<LabEntry> selected;
    for (std::size_t i = 0; i < labs.size(); ++i)
        if (chosen[i]) selected.push_back(labs[i]);
    return selected;
}

std::string programName(const std::string& lab) { return "lab" + lab; }

std::filesystem::path labProgram(const std::filesystem::path& binDir, const std::string& lab) {
    return binDir / programName(lab);
}

std::filesystem::path mistakeProgram(const std::filesystem::path& binDir, const std::string& lab,
                                     const std::string& mistake, const std::string& folder) {
    return binDir / folder / (lab + "." + mistake) / programName(lab);
}

std::filesystem::path referenceFolder(const std::filesystem::path& sourceDir, const std::string& lab) {
    return sourceDir / "autograder" / "references" / lab;
}

std::filesystem::path hiddenReferenceFolder(const std::filesystem::path& sourceDir, const std::string& lab) {
    return sourceDir / "solutions" / lab / "references";
}

std::filesystem::path referenceImagePath(const std::filesystem::path& sourceDir, const std::string& lab,
                                         const std::string& caseName) {
    return referenceFolder(sourceDir, lab) / (caseName + ".png");
}

std::filesystem::path hiddenManifestPath(const std::filesystem::path& sourceDir, const std::string& lab) {
    return sourceDir / "solutions" / lab / "hidden_cases.ini";
}

std::filesystem::path hiddenReferenceImagePath(const std::filesystem::path& sourceDir, const std::string& lab,
                                               const std::string& caseName) {
    return hiddenReferenceFolder(sourceDir, lab) / (caseName + ".png");
}

std::filesystem::path cascadeProgram(const std::filesystem::path& binDir, const std::string& lab) {
    return binDir / "cascade" / programName(lab);
}

bool isExecutable(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::is_regular_file(path, error) && access(path.c_str(), X_OK) == 0;
}

std::filesystem::path executableDir() {
    std::error_code error;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : self.parent_path();
}

} // namespace stoa::grader
