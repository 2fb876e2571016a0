#include "BatchGradeSubmissions.hpp"

#include "ChildProcess.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <sstream>

#include <unistd.h>

namespace stoa::grader {

namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

bool isLabFolderName(const std::string& name) {
    return name.size() > 3 && std::isdigit(static_cast<unsigned char>(name[0])) &&
           std::isdigit(static_cast<unsigned char>(name[1])) && name[2] == '_';
}

bool ignoredEntry(const std::string& name) { return name.empty() || name[0] == '.' || name == "__MACOSX"; }

// Archives come from students: no limit on CPU, but a wall clock and a file size cap.
ProcessLimits unpackLimits() {
    ProcessLimits limits;
    limits.timeoutSeconds = 120.0;
    limits.cpuSeconds = 0;
    limits.addressSpaceBytes = 0;
    limits.fileSizeBytes = 256ull << 20;
    limits.outputLimitBytes = 2048;
    limits.maxProcesses = 0;   // tar runs gzip
    limits.maxTasks = 0;
    limits.isolateNetwork = false;
    limits.ownPidNamespace = false;   // tar and unzip, not student code; strays are still swept
    return limits;
}

} // namespace

std::string studentName(const std::filesystem::path& entry) {
    std::string name = entry.filename().string();
    for (const char* suffix : {".tar.gz", ".tgz", ".zip"})
        if (endsWith(lower(name), suffix)) {
            name.resize(name.size() - std::string(suffix).size());
            break;
        }
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
    return name.empty() ? "_" : name;
}

std::vector<Submission> findSubmissions(const std::filesystem::path& folder, std::vector<std::string>& skipped) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        throw InputError(folder.string(), 0, "not a folder of submissions (expected student folders, .zip or .tar.gz)");
    std::vector<Submission> submissions;
    std::map<std::string, std::filesystem::path> seen;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        std::string name = entry.path().filename().string();
        if (ignoredEntry(name)) continue;
        std::string lowered = lower(name);
        Submission submission;
        submission.source = entry.path();
        if (entry.is_directory(error)) {
            submission.kind = SubmissionKind::Folder;
        } else if (endsWith(lowered, ".zip")) {
            submission.kind = SubmissionKind::Zip;
        } else if (endsWith(lowered, ".tar.gz") || endsWith(lowered, ".tgz")) {
            submission.kind = SubmissionKind::TarGz;
        } else {
            skipped.push_back(name + ": not a folder, .zip or .tar.gz");
            continue;
        }
        submission.student = studentName(entry.path());
        auto [where, inserted] = seen.emplace(submission.student, entry.path());
        if (!inserted)
            throw InputError(folder.string(), 0,
                             "two submissions for student '" + submission.student + "': " +
                                 where->second.filename().string() + " and " + name + "; keep one");
        submissions.push_back(std::move(submission));
    }
    std::sort(submissions.begin(), submissions.end(),
              [](const Submission& a, const Submission& b) { return a.student < b.student; });
    return submissions;
}

std::filesystem::path findLabsFolder(const std::filesystem::path& root) {
    std::error_code error;
    if (std::filesystem::is_directory(root / "labs", error)) return root / "labs";

    std::vector<std::filesystem::path> folders;
    bool hasLabFolders = false;
    for (const auto& entry : std::filesystem::directory_iterator(root, error)) {
        std::string name = entry.path().filename().string();
        if (ignoredEntry(name) || !entry.is_directory(error)) continue;
        folders.push_back(entry.path());
        if (isLabFolderName(name)) hasLabFolders = true;
    }
    if (hasLabFolders) return root;
    if (folders.size() == 1) {
        if (std::filesystem::is_directory(folders[0] / "labs", error)) return folders[0] / "labs";
        for (const auto& entry : std::filesystem::directory_iterator(folders[0], error))
            if (entry.is_directory(error) && isLabFolderName(entry.path().filename().string())) return folders[0];
    }
    std::string looked = (root / "labs").string();
    if (folders.size() == 1) looked += " and " + (folders[0] / "labs").string();
    throw InputError(root.string(), 0, "no labs/ folder in the submission (looked for " + looked + ")");
}

std::filesystem::path findOnPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::stringstream folders(path ? path : "/usr/bin:/bin");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        if (folder.empty()) continue;
        std::filesystem::path candidate = std::filesystem::path(folder) / program;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
}

std::filesystem::path stageSubmission(const Submission& submission, const std::filesystem::path& stageDir) {
    if (submission.kind == SubmissionKind::Folder) return findLabsFolder(std::filesystem::absolute(submission.source));

    std::filesystem::remove_all(stageDir);
    std::filesystem::create_directories(stageDir);
    std::string archive = std::filesystem::absolute(submission.source).string();
    std::vector<std::string> argv;
    if (submission.kind == SubmissionKind::Zip) {
        std::filesystem::path unzip = findOnPath("unzip");
        if (unzip.empty())
            throw InputError(archive, 0, "cannot unpack: 'unzip' is not installed (run .ci/install-deps.sh)");
        argv = {unzip.string(), "-q", "-o", archive, "-d", stageDir.string()};
    } else {
        std::filesystem::path tar = findOnPath("tar");
        if (tar.empty()) throw InputError(archive, 0, "cannot unpack: 'tar' is not installed");
        argv = {tar.string(), "-xzf", archive, "-C", stageDir.string(), "--no-same-owner"};
    }
    ProcessOutcome outcome = runProcess(argv, stageDir, unpackLimits());
    if (!outcome.exitedWith(0)) {
        std::string message = outcome.lastOutputLine();
        throw InputError(archive, 0,
                         "cannot unpack (" + outcome.describe() + ")" + (message.empty() ? "" : ": " + message));
    }
    return findLabsFolder(stageDir);
}

} // namespace stoa::grader
