// Lab 10, part 2: the ground as two images. Read docs/labs/10_crowds.md,
// "Collision and height maps", first. A texel (col, row) covers the square of
// the footprint whose corner nearest footprintMin is
// footprintMin + (col, row) * cellSize; row 0 lies at z = footprintMin.y.

#include "lab10.hpp"

#include <stoa/crowd/CrowdLab.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

bool walkableAt(const CollisionMap& map, glm::vec2 xz) {
    const GroundGrid& grid = map.grid;
    // The point in texel units: (0, 0) is the footprint's corner at its minimum.
    const glm::vec2 texel = (xz - grid.footprintMin) / (grid.footprintMax - grid.footprintMin) *
                            glm::vec2(grid.width, grid.height);
    const int col = static_cast<int>(std::floor(texel.x));
    const int row = static_cast<int>(std::floor(texel.y));
    if (col < 0 || row < 0 || col >= grid.width || row >= grid.height) return false;
    return map.walkable[static_cast<std::size_t>(row) * grid.width + col] != 0;
}

float heightAt(const HeightField& field, glm::vec2 xz) {
    const GroundGrid& grid = field.grid;
    // Samples sit at the texel centres, so texel coordinates minus one half
    // put sample (col, row) at the integer point (col, row).
    const glm::vec2 texel = (xz - grid.footprintMin) / (grid.footprintMax - grid.footprintMin) *
                                glm::vec2(grid.width, grid.height) -
                            0.5f;
    const glm::vec2 clamped = glm::clamp(texel, glm::vec2(0.0f), glm::vec2(grid.width - 1, grid.height - 1));
    const int col0 = static_cast<int>(std::floor(clamped.x));
    const int row0 = static_cast<int>(std::floor(clamped.y));
    const int col1 = std::min(col0 + 1, grid.width - 1);
    const int row1 = std::min(row0 + 1, grid.height - 1);
    const float s = clamped.x - static_cast<float>(col0);
    const float t = clamped.y - static_cast<float>(row0);
    const auto value = [&](int col, int row) { return field.values[static_cast<std::size_t>(row) * grid.width + col]; };
    const float top = value(col0, row0) + (value(col1, row0) - value(col0, row0)) * s;
    const float bottom = value(col0, row1) + (value(col1, row1) - value(col0, row1)) * s;
    const float v = top + (bottom - top) * t;
    return field.heightMin + (field.heightMax - field.heightMin) * v;
}

} // namespace stoa
