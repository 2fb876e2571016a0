#pragma once
// Lab 01's property checks (the cases with a `check` key in cases.ini), for what
// the pictures cannot show. See docs/labs/01_transforms.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab01 {

/// camera_limits: tumble() and look() keep the pitch in [-89, 89] degrees however
/// far the mouse drags, so the view never flips over the pole; dolly() never
/// brings the eye closer to the target than 0.05 (docs: "Cameras").
stoa::CheckResult checkCameraLimits();

/// matrices_map_the_frustum: perspectiveMatrix() of a lens no case uses takes the
/// near and far planes to NDC z = -1 and +1 (and a point between to where the
/// depth formula says), the edges of the field of view to +-1; lookAtMatrix()
/// takes the eye to the origin and the target straight down -Z, with w = 1
/// (docs: "The projection matrix", "The view matrix").
stoa::CheckResult checkMatricesMapTheFrustum();

} // namespace lab01
