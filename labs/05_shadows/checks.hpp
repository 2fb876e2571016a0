#pragma once
// Lab 05's property checks (the cases with a `check` key in cases.ini), for what
// a still picture cannot show. See docs/labs/05_shadows.md, "Checks". Each calls
// your functions on inputs of its own and tests a property the docs state.

#include <stoa/lab/PropertyCheck.hpp>

namespace stoa {
class Program;
}

namespace lab05 {

/// depth_pass_both_faces: renderShadowPass() writes the depth of a square whether
/// its front or its back faces the light (docs: "The two passes").
stoa::CheckResult checkDepthPassBothFaces(const stoa::Program& depthProgram);

/// splits_blend_the_schemes: cascadeSplits() gives count + 1 depths, lambda times
/// the logarithmic split plus (1 - lambda) times the uniform one, from exactly
/// near to exactly far (docs: "The split scheme").
stoa::CheckResult checkSplitsBlendTheSchemes();

/// slice_corners: frustumSliceCorners() returns four corners at the slice's near
/// distance and four at its far distance from the camera, spread as wide as the
/// field of view and the aspect ratio say (docs: "Fitting each cascade").
stoa::CheckResult checkSliceCorners();

/// cascade_depth_reaches_occluders: cascadeLightMatrix()'s depth range reaches
/// towards the light to every corner of the scene's box, so that an occluder
/// outside the slice still casts into it (docs: "Fitting each cascade").
stoa::CheckResult checkCascadeDepthReachesOccluders();

/// cascade_holds_its_slice: every corner of the slice lands inside
/// cascadeLightMatrix()'s box, also when the light shines from the slice's
/// centre through its furthest corner, so that the corner is as far from the
/// light as the bounding sphere reaches (docs: "Fitting each cascade").
stoa::CheckResult checkCascadeHoldsItsSlice();

/// light_box_holds_the_scene: directionalLightMatrix() puts every corner of the
/// scene's box inside [-1, 1]^3, for four light directions, straight down
/// included (docs: "The directional light: an orthographic box fitted to the scene").
stoa::CheckResult checkLightBoxHoldsTheScene();

/// texel_snapping: as the slice moves by less than a texel, a fixed world point
/// moves through the map by whole texels only; as the slice turns, the box keeps
/// its size (docs: "Texel snapping").
stoa::CheckResult checkTexelSnapping();

} // namespace lab05
