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

} // namespace lab07
