#include "LabSandbox.hpp"

#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>

#include <pwd.h>
#include <unistd.h>

namespace stoa::grader {

namespace {

// "05_shadows" -> 5; -1 when the name does not start with two digits.
int labNumber(const std::string& lab) {
    if (lab.size() < 2 || !std::isdigit(static_cast<unsigned char>(lab[0])) ||
        !std::isdigit(static_cast<unsigned char>(lab[1])))
        return -1;
    return (lab[0] - '0') * 10 + (lab[1] - '0');
}

// The shader files of the solutions of the labs before `lab`: what a cascade
// program reads of solutions/ (its C++ is compiled in).
std::vector<std::filesystem::path> earlierSolutionShaders(const std::filesystem::path& sourceDir,
                                                          const std::string& lab) {
    std::vector<std::filesystem::path> files;
    const int number = labNumber(lab);
    std::error_code error;
    for (const auto& folder : std::filesystem::directory_iterator(sourceDir / "solutions", error)) {
        const int earlier = labNumber(folder.path().filename().string());
        if (earlier < 0 || earlier >= number || !folder.is_directory(error)) continue;
        for (auto file = std::filesystem::recursive_directory_iterator(folder.path(), error);
             !error && file != std::filesystem::recursive_directory_iterator(); file.increment(error)) {
            const std::string extension = file->path().extension().string();
            if (extension == ".glsl" || extension == ".vert" || extension == ".frag") files.push_back(file->path());
        }
    }
    return files;
}

// The files the sanitizer runtimes of a sanitizer build are told to read
// (suppressions=FILE in ASAN_OPTIONS, LSAN_OPTIONS, UBSAN_OPTIONS): the lab
// programs inherit that environment, and a runtime that cannot read its file aborts.
std::vector<std::filesystem::path> sanitizerFiles() {
    std::vector<std::filesystem::path> files;
    for (const char* name : {"ASAN_OPTIONS", "LSAN_OPTIONS", "UBSAN_OPTIONS"}) {
        const char* options = std::getenv(name);
        if (!options) continue;
        std::istringstream list(options);
        for (std::string option; std::getline(list, option, ':');)
            if (option.rfind("suppressions=", 0) == 0) files.emplace_back(option.substr(13));
    }
    return files;
}

} // namespace

FileAccess labProgramBaseAccess(const std::filesystem::path& sourceDir, const std::filesystem::path& workRoot) {
    FileAccess access = systemFileAccess();
    for (const char* folder : {"shaders", "assets", "labs"}) access.readable.push_back(sourceDir / folder);
    access.readable.push_back(sourceDir / "autograder" / "references");
    for (const std::filesystem::path& file : sanitizerFiles()) access.readable.push_back(file);
    access.excluded.push_back(workRoot);
    access.excluded.push_back(sourceDir / "solutions");
    return access;
}

std::filesystem::path buildRootOf(const std::filesystem::path& program) {
    std::filesystem::path absolute = std::filesystem::absolute(program).lexically_normal();
    std::error_code error;
    for (std::filesystem::path folder = absolute.parent_path(); !folder.empty(); folder = folder.parent_path()) {
        if (std::filesystem::is_regular_file(folder / "CMakeCache.txt", error)) return folder;
        if (folder == folder.root_path()) break;
    }
    return absolute.parent_path();
}

bool builtFromSolutions(const std::filesystem::path& buildRoot) {
    static std::mutex mutex;
    static std::map<std::filesystem::path, bool> known;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = known.find(buildRoot);
    if (found != known.end()) return found->second;
    bool solutions = false;
    std::ifstream cache(buildRoot / "CMakeCache.txt");
    for (std::string line; std::getline(cache, line);)
        if (line.rfind("STOA_USE_SOLUTIONS:", 0) == 0) {
            std::string value = line.substr(line.find('=') + 1);
            solutions = value == "ON" || value == "1" || value == "TRUE" || value == "YES";
        }
    known[buildRoot] = solutions;
    return solutions;
}

std::filesystem::path userShaderCache() {
    for (const char* name : {"MESA_SHADER_CACHE_DIR", "MESA_GLSL_CACHE_DIR"})
        if (const char* value = std::getenv(name); value && *value) return value;
    if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache && *cache)
        return std::filesystem::path(cache) / "mesa_shader_cache";
    const char* home = std::getenv("HOME");
    if (!home || !*home) {
        const passwd* user = getpwuid(getuid());
        home = user ? user->pw_dir : "/tmp";
    }
    return std::filesystem::path(home) / ".cache" / "mesa_shader_cache";
}

FileAccess labProgramAccess(const CaseJob& job, const RunSettings& settings) {
    FileAccess access = settings.files;
    if (!access.confine) return access;
    const std::filesystem::path build = buildRootOf(job.program);
    access.readable.push_back(build);
    access.readable.push_back(job.program);   // where it lies outside its build (a script in a bin folder)
    if (!job.casesFile.empty()) access.readable.push_back(job.casesFile);
    if (builtFromSolutions(build)) {
        access.readable.push_back(settings.sourceDir / "solutions");
    } else if (job.cascade) {
        for (const std::filesystem::path& shader : earlierSolutionShaders(settings.sourceDir, job.lab))
            access.readable.push_back(shader);
    }
    access.writable.push_back(job.workDir);
    if (!settings.shaderCache.empty()) access.writable.push_back(settings.shaderCache);
    return access;
}

} // namespace stoa::grader
