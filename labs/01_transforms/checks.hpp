#pragma once
// Lab 01's property checks (the cases with a `check` key in cases.ini), for what
// the pictures cannot show. See docs/labs/01_transforms.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab01 {

/// camera_limits: tumble() and look() keep the pitch in [-89, 89] degrees however
/// far the mouse drags, so the view never flips over the pole; dolly() never
/// brings the eye closer to the target than 0.05 (docs: "Cameras").
stoa::CheckResult checkCameraLimits();

} // namespace lab01
