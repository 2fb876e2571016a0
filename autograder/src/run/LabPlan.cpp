#include "LabPlan.hpp"

#include "LabSandbox.hpp"

#include <cstdlib>

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>

namespace stoa::grader {

namespace {

// Refuses to grade a program that predates the student's last edit.
void refuseStalePrograms(const std::vector<PlannedLab>& labs) {
    std::string message;
    std::filesystem::path buildDir;
    for (const PlannedLab& lab : labs) {
        if (!isExecutable(lab.program)) continue;
        const std::vector<std::filesystem::path> newer = staleSources(lab.program, buildDir);
        if (newer.empty()) continue;
        message += "\n  " + lab.program.string() + " is older than";
        for (const std::filesystem::path& file : newer) message += " " + file.string();
        message += " (changed since the last build)";
    }
    if (message.empty()) return;
    const std::string rebuild = buildDir.empty() ? "cmake --build <your build folder>" : "cmake --build " + buildDir.string();
    throw std::runtime_error("the lab programs are older than your files, so they would grade your old code:" + message +
                             "\nrebuild first, then grade again:\n  " + rebuild);
}

} // namespace

std::vector<std::filesystem::path> staleSources(const std::filesystem::path& program, std::filesystem::path& buildDir) {
    std::vector<std::filesystem::path> newer;
    std::ifstream list(program.string() + ".sources");
    std::error_code error;
    const auto built = std::filesystem::last_write_time(program, error);
    if (!list || error) return newer;
    for (std::string line; std::getline(list, line);) {
        if (line.rfind("build ", 0) == 0) buildDir = line.substr(6);
        if (line.rfind("source ", 0) != 0) continue;
        const std::filesystem::path file = line.substr(7);
        const auto changed = std::filesystem::last_write_time(file, error);
        if (!error && changed > built) newer.push_back(file);
    }
    return newer;
}

std::vector<PlannedLab> planLabs(const Options& options, const Environment& env, bool requirePrograms) {
    std::vector<LabEntry> labs = selectLabs(findLabs(env.sourceDir), options.labs);

    std::vector<PlannedLab> planned;
    for (const LabEntry& entry : labs) {
        PlannedLab lab;
        lab.lab = entry.lab;
        lab.manifest = loadManifest(entry.manifestPath);
        lab.program = labProgram(env.binDir, entry.lab);
        if (isExecutable(cascadeProgram(env.binDir, entry.lab))) lab.cascadeProgram = cascadeProgram(env.binDir, entry.lab);
        std::filesystem::path hidden = hiddenManifestPath(env.sourceDir, entry.lab);
        std::error_code error;
        if (std::filesystem::is_regular_file(hidden, error)) addHiddenCases(lab, hidden);
        for (const CaseSpec& spec : lab.manifest.cases)
            if (options.cases.empty() ||
                std::find(options.cases.begin(), options.cases.end(), spec.name) != options.cases.end())
                lab.cases.push_back(spec);
        planned.push_back(std::move(lab));
    }

    for (const std::string& name : options.cases) {
        bool known = std::any_of(planned.begin(), planned.end(),
                                 [&](const PlannedLab& lab) { return lab.manifest.find(name) != nullptr; });
        if (known) continue;
        std::string choices;
        for (const PlannedLab& lab : planned)
            choices += "\n  " + lab.lab + ": " + (lab.manifest.cases.empty() ? "(no cases)" : lab.manifest.caseNames());
        throw UsageError("unknown case '" + name + "'; the cases are:" + choices);
    }

    std::vector<PlannedLab> kept;
    for (PlannedLab& lab : planned) {
        if (lab.cases.empty()) continue;
        if (requirePrograms && !isExecutable(lab.program) && lab.cascadeProgram.empty()) {
            env.err << "note: lab " << lab.lab << " is not built (no program " << lab.program.string()
                    << "); skipping it\n";
            continue;
        }
        kept.push_back(std::move(lab));
    }
    if (requirePrograms) refuseStalePrograms(kept);
    return kept;
}

void addHiddenCases(PlannedLab& lab, const std::filesystem::path& hiddenManifest) {
    LabManifest hidden = loadManifest(hiddenManifest);
    if (hidden.lab != lab.lab)
        throw InputError(hidden.file, 0, "says lab = " + hidden.lab + ", but it is in the folder of lab " + lab.lab);
    for (CaseSpec& spec : hidden.cases) {
        if (lab.manifest.find(spec.name))
            throw InputError(hidden.file, spec.line, "hidden case '" + spec.name + "' has the name of a case in " +
                                                         lab.manifest.file + "; give it another name");
        spec.visibility = Visibility::Hidden;   // implied by where it lives
        lab.manifest.cases.push_back(std::move(spec));
    }
    lab.hiddenManifest = hiddenManifest;
}

std::vector<CaseJob> caseJobs(const PlannedLab& lab, const std::filesystem::path& program,
                              const std::filesystem::path& sourceDir, const std::filesystem::path& workDir,
                              bool cascade) {
    std::vector<CaseJob> jobs;
    const bool sanitized = builtWithAddressSanitizer();
    std::map<std::string, double> publicTimes = readRenderTimes(renderTimesPath(referenceFolder(sourceDir, lab.lab)));
    std::map<std::string, double> hiddenTimes;
    if (!lab.hiddenManifest.empty())
        hiddenTimes = readRenderTimes(renderTimesPath(hiddenReferenceFolder(sourceDir, lab.lab)));
    for (const CaseSpec& spec : lab.cases) {
        bool hidden = !lab.hiddenManifest.empty() && std::filesystem::path(spec.file) == lab.hiddenManifest;
        CaseJob job;
        job.lab = lab.lab;
        job.program = program;
        job.spec = spec;
        job.reference = hidden ? hiddenReferenceImagePath(sourceDir, lab.lab, spec.name)
                               : referenceImagePath(sourceDir, lab.lab, spec.name);
        job.workDir = cascade ? workDir / "cascade" / lab.lab / spec.name : workDir / lab.lab / spec.name;
        job.cascade = cascade;
        const std::map<std::string, double>& times = hidden ? hiddenTimes : publicTimes;
        auto time = times.find(spec.name);
        job.timeouts = caseTimeouts(time == times.end() ? 0.0 : time->second, sanitized);
        // The lab program reads the case from the manifest the grader planned from.
        if (!spec.file.empty()) job.casesFile = std::filesystem::absolute(spec.file);
        jobs.push_back(std::move(job));
    }
    return jobs;
}

RunSettings runSettings(const Options& options, const std::filesystem::path& sourceDir,
                        const std::filesystem::path& workDir) {
    RunSettings settings;
    settings.sourceDir = sourceDir;
    settings.files = labProgramBaseAccess(sourceDir, workDir);
    for (const std::filesystem::path& folder : options.privateDirs) settings.files.excluded.push_back(folder);
    // To try the fallback where Landlock is there (the instructor guide, "Files").
    if (const char* sandbox = std::getenv("STOA_GRADE_FILE_SANDBOX"); sandbox && std::string(sandbox) == "mounts")
        settings.files.preferMounts = true;
    settings.shaderCache = options.shaderCache.empty() ? userShaderCache() : options.shaderCache;
    // Made here: a confined lab program could not make it. The user's default may
    // fail quietly (Mesa then runs without a cache); a folder asked for may not.
    std::error_code error;
    std::filesystem::create_directories(settings.shaderCache, error);
    if (!options.shaderCache.empty() && !std::filesystem::is_directory(settings.shaderCache))
        throw InputError(options.shaderCache.string(), 0,
                         "--shader-cache: cannot create the folder" + (error ? ": " + error.message() : ""));
    // Without --timeout, each case's limit comes from its recorded render time;
    // the 60 s here is for what runs outside gradeCases() (references, --info).
    settings.caseTimeouts = options.timeoutSeconds <= 0.0;
    settings.limits = defaultLimits(settings.caseTimeouts ? 60.0 : options.timeoutSeconds);
    settings.backend = options.backend;
    return settings;
}

} // namespace stoa::grader
