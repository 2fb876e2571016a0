#include "HeadlessRender.hpp"

#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/lab/LabApp.hpp>

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

int renderHeadless(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options) {
    const CaseSpec& spec = findCase(manifest, options.renderCase);
    HeadlessContext context(options.backend);
    enableDebugOutput();
    LabResources resources(splitSearchPath(info.shaderPath));
    lab.initialize(resources);
    lab.loadCase(spec);
    spec.requireAllKeysUsed();

    renderCaseImage(lab, resources, spec).savePng(options.output);
    return kExitOk;
}

} // namespace stoa::detail
