#pragma once
// Lab 09's property checks (the cases with a `check` key in cases.ini), for what
// the pictures cannot show. See docs/labs/09_ssao.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace stoa {
class AmbientOcclusionPass;
class DeferredRenderer;
} // namespace stoa

namespace lab09 {

/// kernel_in_order: ssaoKernel() draws its numbers in the order the docs give
/// (x, y, z, then the length, sample by sample), so that every machine and
/// every compiler makes the same kernel from the same seed (docs: "The sample kernel").
stoa::CheckResult checkKernelInOrder();

/// range_check_from_the_point: a wall, and a strip 2 radii in front of it
/// covering the left half of the view; a pixel of the wall just beside the
/// strip's edge, with one kernel sample that lands behind the strip. The range
/// check weighs that occluder by its distance from P, r / |P.z - sceneZ| = 1/2,
/// so the raw occlusion there is 0.5 (docs: "The range check"). Draws through
/// the lab's renderer and occlusion pass with a kernel and noise of its own.
stoa::CheckResult checkRangeCheckFromThePoint(stoa::DeferredRenderer& renderer, stoa::AmbientOcclusionPass& occlusion);

/// blur_footprint: the blur pass of a 37 x 29 picture of random raw levels is,
/// at every pixel, the mean of its 4 x 4 window (offsets -2 to 1 on each axis)
/// with the neighbours outside the picture left out (docs: "The blur").
stoa::CheckResult checkBlurFootprint(stoa::DeferredRenderer& renderer, stoa::AmbientOcclusionPass& occlusion);

} // namespace lab09
