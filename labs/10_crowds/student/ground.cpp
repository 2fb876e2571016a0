// Lab 10, part 2: the ground as two images. Read docs/labs/10_crowds.md,
// "Collision and height maps", first. A map's grid (GroundGrid, in
// stoa/crowd/GroundMaps.hpp) lays width x height texels over the footprint
// [footprintMin, footprintMax] (x, z); texel (col, row) is stored at
// [row * width + col], and row 0 lies along z = footprintMin.y.

#include "lab10.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/crowd/CrowdLab.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

bool walkableAt(const CollisionMap& map, glm::vec2 xz) {
    // TODO(lab10): turn (x, z) into texel units (0 at footprintMin, width and
    // height at footprintMax), take the texel that holds the point, and return
    // whether map.walkable says 1 there. Outside the map: not walkable
    // (docs: "From a point to a texel").
    (void)map;
    (void)xz;
    throw NotImplemented("walkableAt()");
}

float heightAt(const HeightField& field, glm::vec2 xz) {
    // TODO(lab10): the values are samples at the texel centres. Read the four
    // samples around the point and blend them bilinearly (clamp to the edge
    // samples outside them), then map the value from [0, 1] to
    // [field.heightMin, field.heightMax] (docs: "Bilinear height").
    (void)field;
    (void)xz;
    throw NotImplemented("heightAt()");
}

} // namespace stoa
