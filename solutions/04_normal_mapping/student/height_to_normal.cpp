// Lab 04, part 2: a normal map from a height map (bump mapping).
// Read docs/labs/04_normal_mapping.md, "From heights to normals", first.
// The height map is a 1-channel Image, row 0 at the top; the result is an RGB
// Image of the same size that the fragment shader samples as a normal map.

#include "lab04.hpp"

#include <stoa/core/Assert.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/image/HeightMap.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace stoa {

Image normalMapFromHeight(const Image& height, float strength) {
    STOA_ASSERT(height.channels() == 1 && !height.empty(),
                "normalMapFromHeight(): pass a 1-channel height map (loadHeightMap() returns one)");
    STOA_ASSERT(strength > 0.0f, "normalMapFromHeight(): strength must be positive");
    const int width = height.width(), rows = height.height();
    // Wrap around the borders: the maps tile, so the texel left of column 0 is the last column.
    auto h = [&](int x, int y) {
        x = (x + width) % width;
        y = (y + rows) % rows;
        return static_cast<float>(height.data()[static_cast<std::size_t>(y) * width + x]) / 255.0f;
    };

    Image normals(width, rows, 3);
    for (int y = 0; y < rows; ++y) {
        for (int x = 0; x < width; ++x) {
            const float dhdu = (h(x + 1, y) - h(x - 1, y)) * 0.5f;
            const float dhdv = (h(x, y - 1) - h(x, y + 1)) * 0.5f;  // row y - 1 is above: larger v
            const glm::vec3 n = glm::normalize(glm::vec3(-strength * dhdu, -strength * dhdv, 1.0f));
            const glm::vec3 packed = glm::round((n * 0.5f + 0.5f) * 255.0f);
            normals.setPixel(x, y, glm::u8vec4(glm::u8vec3(packed), 255));
        }
    }
    return normals;
}

} // namespace stoa
