#pragma once
// The interactive app: a lab in a window with the cameras, case jumps, the
// in-window comparison, shader reload, the UI panel. Private to framework/src/lab/.

#include "LabCommandLine.hpp"

#include <stoa/lab/Lab.hpp>

namespace stoa::detail {

/// Opens the window at the first case (or --case's), runs it until it closes;
/// the exit status (kExitNotAttempted for a --screenshot of a stub).
int runWindow(Lab& lab, const LabBuildInfo& info, const LabManifest& manifest, const Options& options, int argc,
              char** argv);

} // namespace stoa::detail
