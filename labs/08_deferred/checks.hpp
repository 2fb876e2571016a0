#pragma once
// Lab 08's property checks (the cases with a `check` key in cases.ini), for
// what the pictures show too faintly, or never, to grade. See
// docs/labs/08_deferred.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab08 {

/// reach_solves_the_falloff: lightReach() of lights with every kind of
/// attenuation (quadratic, linear only, none, too dim to show) is the distance
/// where the brightest channel has fallen to the cut-off: I(R) = cut-off, 0 when
/// the light never reaches it, a very large distance when it never falls off
/// (docs: "How far a light reaches").
stoa::CheckResult checkReachSolvesTheFalloff();

/// tile_ranges_hold_the_sphere: lightTileRange() of spheres in and around a
/// picture of 13 x 9 tiles holds every tile that a point of the sphere lands in
/// (docs: "Which tiles a light touches").
stoa::CheckResult checkTileRangesHoldTheSphere();

/// tile_lists_match_the_ranges: buildTileLightLists() lists in each tile exactly
/// the lights whose lightTileRange() holds the tile and whose span of depths
/// meets the tile's, in increasing order, with offsets as the page lays them out
/// (docs: "Building the lists", "Depth bounds").
stoa::CheckResult checkTileListsMatchTheRanges();

} // namespace lab08
