#pragma once
// Lab 04's property checks (the cases with a `check` key in cases.ini), for
// what the pictures cannot show. See docs/labs/04_normal_mapping.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab04 {

/// normal_map_wraps: normalMapFromHeight() treats the height map as a tile that
/// repeats. Shifting the height map by a few texels (around, as a tile) must shift
/// its normal map by the same texels and change nothing else: a texel on the border
/// takes its missing neighbour from the opposite border, as the texture's
/// GL_REPEAT does when the wall samples it.
stoa::CheckResult checkNormalMapWraps();

} // namespace lab04
