// Lab 04, part 2: a normal map from a height map (bump mapping).
// Read docs/labs/04_normal_mapping.md, "From heights to normals", first.
// The height map is a 1-channel Image, row 0 at the top; the result is an RGB
// Image of the same size that the fragment shader samples as a normal map.

#include "lab04.hpp"

#include <stoa/core/Assert.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/image/HeightMap.hpp>

#include <glm/glm.hpp>

namespace stoa {

Image normalMapFromHeight(const Image& height, float strength) {
    STOA_ASSERT(height.channels() == 1 && !height.empty(),
                "normalMapFromHeight(): pass a 1-channel height map (loadHeightMap() returns one)");
    STOA_ASSERT(strength > 0.0f, "normalMapFromHeight(): strength must be positive");
    // TODO(lab04): for every texel (x, y):
    //  1. h = value / 255. Central differences, wrapping around the borders:
    //       dh/du = (h(x+1, y) - h(x-1, y)) / 2
    //       dh/dv = ?   careful: rows go DOWN the image, v goes UP.
    //  2. n = normalize(-strength * dh/du, -strength * dh/dv, 1).
    //  3. Pack n from [-1, 1] into [0, 255]: round((n * 0.5 + 0.5) * 255) into r, g, b.
    throw NotImplemented("normalMapFromHeight()");
}

} // namespace stoa
