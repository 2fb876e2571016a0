#include "BatchGradeSubmissions.hpp"

#include "ChildProcess.hpp"
#include "ReferenceGuard.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
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

// Copies `from` into `to` (which exists): folders and regular files, symbolic
// links as links (never followed: a link to a classmate's file stays a link the
// confined build cannot follow); sockets, pipes and devices are left out.
void copyFolder(const std::filesystem::path& from, const std::filesystem::path& to, std::uintmax_t& bytes) {
    for (const auto& entry : std::filesystem::directory_iterator(from)) {
        const std::filesystem::path target = to / entry.path().filename();
        const std::filesystem::file_status status = entry.symlink_status();
        if (std::filesystem::is_symlink(status)) {
            std::filesystem::copy_symlink(entry.path(), target);
        } else if (std::filesystem::is_directory(status)) {
            std::filesystem::create_directory(target);
            copyFolder(entry.path(), target, bytes);
        } else if (std::filesystem::is_regular_file(status)) {
            bytes += entry.file_size();
            if (bytes > kMaxSubmissionBytes)
                throw InputError(from.string(), 0, "the submission holds more than " +
                                                       std::to_string(kMaxSubmissionBytes >> 20) +
                                                       " MiB; hand in the labs/ folder only");
            std::filesystem::copy_file(entry.path(), target);
        }
    }
}

std::string readBytes(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
}

InputFile recordFile(const std::filesystem::path& path, const std::string& name) {
    InputFile input;
    input.path = name;
    std::error_code error;
    std::string bytes = std::filesystem::is_symlink(std::filesystem::symlink_status(path, error))
                            ? "link -> " + std::filesystem::read_symlink(path, error).string()
                            : readBytes(path);
    input.size = bytes.size();
    input.hash = contentHash(bytes);
    return input;
}

} // namespace

std::vector<InputFile> recordInputs(const Submission& submission) {
    std::vector<InputFile> inputs;
    const std::filesystem::path root = std::filesystem::absolute(submission.source);
    if (submission.kind != SubmissionKind::Folder) {
        inputs.push_back(recordFile(root, ""));
        return inputs;
    }
    std::error_code error;
    for (auto entry = std::filesystem::recursive_directory_iterator(root, error);
         !error && entry != std::filesystem::recursive_directory_iterator(); entry.increment(error)) {
        const std::filesystem::file_status status = entry->symlink_status();
        if (std::filesystem::is_regular_file(status) || std::filesystem::is_symlink(status))
            inputs.push_back(recordFile(entry->path(), entry->path().lexically_relative(root).generic_string()));
    }
    std::sort(inputs.begin(), inputs.end(), [](const InputFile& a, const InputFile& b) { return a.path < b.path; });
    return inputs;
}

std::vector<std::string> changedInputs(const std::vector<InputFile>& before, const std::vector<InputFile>& after) {
    std::map<std::string, const InputFile*> earlier;
    for (const InputFile& input : before) earlier[input.path] = &input;
    std::vector<std::string> changed;
    auto shown = [](const std::string& path) { return path.empty() ? std::string("(the archive)") : path; };
    for (const InputFile& input : after) {
        auto found = earlier.find(input.path);
        if (found == earlier.end()) {
            changed.push_back(shown(input.path) + " (new)");
            continue;
        }
        if (!(*found->second == input)) changed.push_back(shown(input.path));
        earlier.erase(found);
    }
    for (const auto& [path, input] : earlier) changed.push_back(shown(path) + " (gone)");
    return changed;
}

std::string inputsText(const std::vector<InputFile>& inputs) {
    std::string text;
    char hash[17];
    for (const InputFile& input : inputs) {
        std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(input.hash));
        text += std::string(hash) + "  " + std::to_string(input.size) + "  " +
                (input.path.empty() ? "(the archive)" : input.path) + "\n";
    }
    return text;
}

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
    std::filesystem::remove_all(stageDir);
    std::filesystem::create_directories(stageDir);
    if (submission.kind == SubmissionKind::Folder) {
        std::uintmax_t bytes = 0;
        copyFolder(std::filesystem::absolute(submission.source), stageDir, bytes);
        return findLabsFolder(stageDir);
    }

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
    ProcessLimits limits = unpackLimits();
    // The archive tool writes only into the stage folder (an entry "../x" or a
    // link out of it goes nowhere) and reads only the archive.
    limits.files = systemFileAccess();
    limits.files.readable.push_back(archive);
    limits.files.writable.push_back(stageDir);
    ProcessOutcome outcome = runProcess(argv, stageDir, limits);
    if (!outcome.exitedWith(0)) {
        std::string message = outcome.lastOutputLine();
        throw InputError(archive, 0,
                         "cannot unpack (" + outcome.describe() + ")" + (message.empty() ? "" : ": " + message));
    }
    return findLabsFolder(stageDir);
}

} // namespace stoa::grader
