#pragma once
// Lab 07's property checks (the cases with a `check` key in cases.ini), for
// what the pictures never show. See docs/labs/07_picking.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab07 {

/// slab_test_table: rayHitsBox() on a table of rays and boxes whose answers are
/// known: along an axis, slanted, from inside the box, with the box behind the
/// ray or beyond tMax, parallel to a slab inside and outside it, boxes away from
/// the origin. It must say hit or miss, and on a hit set tEntry to where the ray
/// enters (0 from inside) (docs: "The slab test").
stoa::CheckResult checkSlabTestTable();

/// bvh_cheapest_split: buildBvh() splits the root at the cheapest of all the
/// candidate planes, in two layouts where it is one the graded scenes never
/// need: a child of a single far triangle, and the last plane, between the last
/// two bins (docs: "Where to split").
stoa::CheckResult checkBvhCheapestSplit();

/// bvh_structure: buildBvh() makes a sound tree over 300 scattered triangles and
/// over 150 that spread out so fast that only the depth limit ends the tree:
/// every triangle in exactly one leaf, every box holding what lies below it,
/// no leaf above maxLeafSize that could be split, nothing deeper than
/// kMaxBvhDepth (docs: "The BVH").
stoa::CheckResult checkBvhStructure();

/// closest_point_on_triangle: closestPointOnTriangle() against the nearest
/// point found another way (the plane's, if inside, else the nearest of the
/// edges'), for 1,600 points around four triangles: every corner's, edge's and
/// the face's region (docs: "Closest point on a triangle").
stoa::CheckResult checkClosestPointOnTriangle();

/// deep_tree_walks: trianglesNearSphere() and intersectBvh() on a tree
/// kMaxBvhDepth levels deep, whose every box the sphere and the ray meet, each
/// level leaving a node behind on the walk's stack: every triangle once, and
/// the nearest hit (docs: "Finding the triangles", "Nearest hit").
stoa::CheckResult checkDeepTreeWalks();

/// fixed_step_bookkeeping: advanceSimulation() over frames of uneven lengths,
/// some exactly one step: the accumulator keeps less than a step, the simulated
/// time is a whole number of steps, and the two add up to the frames' time
/// (docs: "A fixed time step").
stoa::CheckResult checkFixedStepBookkeeping();

/// triangle_hits_on_the_edges: rayHitsTriangle() for rays straight down onto a
/// unit right triangle, inside, on each edge, at a corner and outside: a hit on
/// the edges too, and t, u and v set (docs: "Ray and triangle").
stoa::CheckResult checkTriangleHitsOnTheEdges();

/// ray_starts_on_the_near_plane: rayThroughPixel() for three pixels of a camera
/// whose near plane is 0.5 m away: the ray starts on the near plane and points
/// to the pixel's point on the far plane (docs: "A ray through a pixel").
stoa::CheckResult checkRayStartsOnTheNearPlane();

} // namespace lab07
