// Lab 11, part 1: picking through the stencil buffer. Read docs/labs/11_editor.md,
// "Picking with the stencil buffer", first.

#include "lab11.hpp"

#include <algorithm>

namespace stoa {

int objectAtPixel(const StencilReadback& stencil, glm::ivec2 mouse, int radiusPixels) {
    if (mouse.x < 0 || mouse.y < 0 || mouse.x >= stencil.width || mouse.y >= stencil.height) return -1;
    // Window rows count down from the top, read-back rows up from the bottom.
    const int row = stencil.height - 1 - mouse.y;
    const auto valueAt = [&](int x, int y) { return stencil.values[static_cast<std::size_t>(y) * stencil.width + x]; };
    if (valueAt(mouse.x, row) != 0) return valueAt(mouse.x, row) - 1;

    int best = -1;
    long bestDistance = static_cast<long>(radiusPixels) * radiusPixels + 1;
    for (int y = std::max(0, row - radiusPixels); y <= std::min(stencil.height - 1, row + radiusPixels); ++y)
        for (int x = std::max(0, mouse.x - radiusPixels); x <= std::min(stencil.width - 1, mouse.x + radiusPixels); ++x) {
            const long distance = static_cast<long>(x - mouse.x) * (x - mouse.x) + static_cast<long>(y - row) * (y - row);
            if (valueAt(x, y) != 0 && distance < bestDistance) {
                bestDistance = distance;
                best = valueAt(x, y) - 1;
            }
        }
    return best;
}

} // namespace stoa
