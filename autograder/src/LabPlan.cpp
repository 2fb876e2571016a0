#include "LabPlan.hpp"

#include <algorithm>

namespace stoa::grader {

std::vector<PlannedLab> planLabs(const Options& options, const Environment& env, bool requirePrograms) {
    std::vector<LabEntry> labs = selectLabs(findLabs(env.sourceDir), options.labs);

    std::vector<PlannedLab> planned;
    for (const LabEntry& entry : labs) {
        PlannedLab lab;
        lab.lab = entry.lab;
        lab.manifest = loadManifest(entry.manifestPath);
        lab.program = labProgram(env.binDir, entry.lab);
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
        if (requirePrograms && !isExecutable(lab.program)) {
            env.err << "note: lab " << lab.lab << " is not built (no program " << lab.program.string()
                    << "); skipping it\n";
            continue;
        }
        kept.push_back(std::move(lab));
    }
    return kept;
}

std::vector<CaseJob> caseJobs(const PlannedLab& lab, const std::filesystem::path& program,
                              const std::filesystem::path& sourceDir, const std::filesystem::path& workDir) {
    std::vector<CaseJob> jobs;
    for (const CaseSpec& spec : lab.cases)
        jobs.push_back(CaseJob{lab.lab, program, spec, referenceImagePath(sourceDir, lab.lab, spec.name),
                               workDir / lab.lab / spec.name});
    return jobs;
}

RunSettings runSettings(const Options& options) {
    RunSettings settings;
    settings.limits = defaultLimits(options.timeoutSeconds);
    settings.backend = options.backend;
    return settings;
}

} // namespace stoa::grader
