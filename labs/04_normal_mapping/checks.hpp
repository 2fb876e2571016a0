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

/// normal_map_encoding: normalMapFromHeight() of flat height maps stores the
/// unbent normal (0, 0, 1) as round((n * 0.5 + 0.5) * 255) = (128, 128, 255) in
/// every texel (docs: "From heights to normals").
stoa::CheckResult checkNormalMapEncoding();

/// tangents_without_nans: computeTangents() on a mesh with a triangle whose uvs
/// lie on a line (det = 0): that triangle adds nothing, the good triangle's
/// vertices keep its tangent, and a vertex that only the bad triangle uses still
/// gets a finite unit tangent perpendicular to its normal, with w = +1 (docs:
/// "The tangent frame").
stoa::CheckResult checkTangentsWithoutNans();

/// tangents_follow_the_uvs: computeTangents() of a triangle whose uvs are a
/// linear map of its position (scaled, sheared, mirrored, turned; never by whole
/// units only): the tangent points where u grows, and w is the sign that makes
/// w cross(N, T) point where v grows (docs: "The tangent frame", "Handedness").
stoa::CheckResult checkTangentsFollowTheUvs();

} // namespace lab04
