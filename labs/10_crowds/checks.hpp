#pragma once
// Lab 10's property checks (the cases with a `check` key in cases.ini), for
// what the pictures show too faintly to grade. See docs/labs/10_crowds.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab10 {

/// heights_at_texel_centres: the height map's values are samples at the texel
/// centres, so heightAt() at a texel's centre is that texel's height exactly,
/// and halfway between four neighbouring centres it is their mean. Tried on a
/// field of random values over a footprint that does not start at the origin;
/// outside the footprint, each corner's height holds (the clamp).
stoa::CheckResult checkHeightsAtTexelCentres();

/// walkable_at_texels: walkableAt() reads the texel that holds the point, on a
/// map that is not square (rows and columns apart), and nothing on or past the
/// footprint's edges is walkable.
stoa::CheckResult checkWalkableAtTexels();

/// blended_normals_unit: blendMd2Frames() gives unit normals for every t
/// between the frames (two unit normals blended are shorter than one), the
/// first frame at t = 0, and positions on the straight line between the two.
stoa::CheckResult checkBlendedNormalsUnit();

/// layers_first_that_fires: arbitrateLayers() returns the first layer from the
/// top whose conditions all hold, on stacks and senses of its own, -1 when no
/// layer fires (a stack whose every layer has conditions: no graded world has one).
stoa::CheckResult checkLayersFirstThatFires();

} // namespace lab10
