#pragma once
// Lab 06's property checks (the cases with a `check` key in cases.ini), for what
// the field's pictures cannot show. See docs/labs/06_culling.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab06 {

/// sphere_turned_about_x: worldBoundingSphere() under a model that stretches an
/// object along one axis and then turns it about X (the field only turns its
/// objects about Y): every point of the object's sphere still lies inside the
/// world sphere, and the world sphere is no larger than the longest column of
/// the model matrix says (docs: "A sphere in world space").
stoa::CheckResult checkSphereTurnedAboutX();

/// planes_bound_clip_space: frustumPlanes() of a camera that looks down and
/// sideways gives six unit normals, and each plane, in the order left, right,
/// bottom, top, near, far, says inside exactly where its side of the clip volume
/// does, for points in and around the volume (docs: "The frustum's planes").
stoa::CheckResult checkPlanesBoundClipSpace();

/// levels_of_detail: levelOfDetail(q, n) on the page's table for four levels,
/// its ends and other level counts; -1 for q <= 0 (docs: "Level of detail").
stoa::CheckResult checkLevelsOfDetail();

/// inside_at_the_boundary: on the six planes of the box [-1, 1]^3, a sphere that
/// touches a side from outside (s(c) = -r) and a box whose face lies on a side's
/// plane (s(p+) = 0) are kept; a quarter further out they are culled (docs:
/// "Is it inside?").
stoa::CheckResult checkInsideAtTheBoundary();

} // namespace lab06
