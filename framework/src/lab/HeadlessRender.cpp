#include "HeadlessRender.hpp"

#include "ProgramName.hpp"

#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/lab/LabApp.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace stoa::detail {

void throwIfShaderStubs(const LabResources& resources) {
    for (const auto& program : resources.programs()) {
        if (program->stubs().empty()) continue;
        const ShaderStub& stub = program->stubs().front();
        throw ShaderNotImplemented(stub.function + " (" + stub.file + ":" + std::to_string(stub.line) + ")");
    }
}

Image renderCaseImage(Lab& lab, const LabResources& resources, const CaseSpec& spec) {
    Framebuffer target(spec.width, spec.height, FramebufferOptions{});
    target.bind();
    lab.render({spec.width, spec.height});
    throwIfShaderStubs(resources);
    Image image = target.readColor();
    Framebuffer::bindDefault();
    return image;
}

// Runs one property check and prints its verdict as one line (the grader shows
// the last line of output as the case's reason). 0 when it holds, else kExitCheckFailed.
// (A check runs C++ only: the GLSL stubs of the lab's programs do not stop it.)
int runOneCheck(Lab& lab, const CaseSpec& spec) {
    spec.requireAllKeysUsed();
    const CheckResult result = lab.runCheck(spec);
    std::printf("%s\n", checkVerdictLine(spec.name, result.holds ? CheckVerdict::Holds : CheckVerdict::DoesNotHold,
                                        result.message)
                           .c_str());
    std::fflush(stdout);
    return result.holds ? kExitOk : kExitCheckFailed;
}

int runChecks(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options) {
    std::vector<const CaseSpec*> selected;
    for (const CaseSpec& spec : manifest.cases)
        if (!spec.check.empty() && (options.check == "all" || spec.name == options.check)) selected.push_back(&spec);
    if (selected.empty() && options.check == "all") {
        // `--check all` on a lab without checks: nothing to run is not an error.
        std::printf("%s has no property checks\n", programName(info).c_str());
        return kExitOk;
    }
    if (selected.empty()) {
        std::string checks;
        for (const CaseSpec& spec : manifest.cases)
            if (!spec.check.empty()) checks += (checks.empty() ? "" : ", ") + spec.name;
        throw InputError(manifest.file, 0,
                         "no property check '" + options.check + "' (checks: " + (checks.empty() ? "none" : checks) +
                             "; 'all' runs every one)");
    }
    HeadlessContext context(options.backend);
    enableDebugOutput();
    LabResources resources(splitSearchPath(info.shaderPath));
    lab.initialize(resources);
    int failed = 0, notAttempted = 0;
    for (const CaseSpec* spec : selected) {
        try {
            if (runOneCheck(lab, *spec) != kExitOk) ++failed;
        } catch (const NotImplemented& stub) {
            std::printf("%s\n",
                        checkVerdictLine(spec->name, CheckVerdict::NotAttempted, notImplementedText(stub.describe(info.name)))
                            .c_str());
            ++notAttempted;
        }
    }
    if (selected.size() > 1)
        std::printf("%zu of %zu checks hold\n", selected.size() - static_cast<std::size_t>(failed + notAttempted),
                    selected.size());
    return failed > 0 ? kExitCheckFailed : notAttempted > 0 ? kExitNotAttempted : kExitOk;
}

int renderHeadless(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options) {
    const CaseSpec& spec = findCase(manifest, options.renderCase);
    HeadlessContext context(options.backend);
    enableDebugOutput();
    LabResources resources(splitSearchPath(info.shaderPath));
    lab.initialize(resources);
    // A property check renders no picture: the exit status is the verdict.
    if (!spec.check.empty()) return runOneCheck(lab, spec);
    lab.loadCase(spec);
    spec.requireAllKeysUsed();

    renderCaseImage(lab, resources, spec).savePng(options.output);
    return kExitOk;
}

} // namespace stoa::detail
