#pragma once
// Rendering a case without a window: what `--render` writes and what the
// in-window comparison shows as "yours". Private to framework/src/lab/.

#include "LabCommandLine.hpp"

#include <stoa/image/Image.hpp>
#include <stoa/lab/Lab.hpp>

#include <stdexcept>

namespace stoa::detail {

/// A GLSL stub still in place, reported like a C++ NotImplemented.
struct ShaderNotImplemented : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Throws ShaderNotImplemented for the first GLSL stub still in a program.
void throwIfShaderStubs(const LabResources& resources);

/// The picture of a case whose scene is loaded: rendered at the case's size into
/// an offscreen target, as `--render` writes it and the grader compares it.
/// Throws NotImplemented or ShaderNotImplemented while a stub is in place.
Image renderCaseImage(Lab& lab, const LabResources& resources, const CaseSpec& spec);

/// `--check NAME|all`: the lab's property checks, headless, each with its
/// one-line verdict; kExitCheckFailed when one does not hold.
int runChecks(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options);

/// `--render NAME --output FILE`: a headless context, the case, the PNG.
int renderHeadless(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options);

} // namespace stoa::detail
