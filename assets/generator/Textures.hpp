#pragma once
// The textures of the Acropolis scene, painted in code. All tile seamlessly
// (the meshes repeat them) and are made from fixed seeds (see Noise.hpp).
// Row 0 is the top of the image, as stoa::Image stores it.

#include <stoa/image/Image.hpp>

namespace stoa::assets {

/// Limestone floor slabs (1 m x 0.5 m in a 2 m repeat, rows offset by half a
/// slab) with dark joints; RGB.
Image floorDiffuse(int size = 512);

/// White marble with grey-blue veins; RGB.
Image columnDiffuse(int size = 256);
/// How polished the marble is: bright on the stone, dull in the veins; grey.
Image columnSpecular(int size = 256);

/// The wall's stone blocks: 8 courses of 4 blocks per repeat, each course
/// offset by half a block, in light mortar. RGB. Matches wallHeight().
Image wallDiffuse(int size = 256);
/// Height of the same blocks: mortar low (about 0.1), block faces high (up to 1)
/// with rounded edges and a rough surface; grey, 0 = deepest.
Image wallHeight(int size = 256);

/// Weathered limestone in horizontal courses for the temple; RGBA, alpha 255.
Image templeDiffuse(int size = 256);

} // namespace stoa::assets
