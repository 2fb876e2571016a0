// Lab 08, part 3: tiled light culling on the CPU. Read docs/labs/08_deferred.md,
// "Tiled shading". The app cuts the picture into square tiles, asks
// buildTileLightLists() which lights can reach each one, and hands the lists
// to one full-screen pass (shaders/deferred/tiled.frag), where each pixel
// loops over its own tile's lights only.

#include "lab08.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/render/DeferredShading.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace stoa {

TileRange lightTileRange(const LightSphere& light, const glm::mat4& projection, float near, const TileGrid& grid) {
    // TODO(lab08): a sphere wholly behind the near plane covers nothing; one
    // that crosses it may cover any tile. Otherwise project the eight corners
    // of the box around the sphere (view space), keep the rectangle they span
    // in normalised device coordinates, clip it to the picture, and turn it
    // into the first and last tile on each axis (docs: "Tiled shading").
    (void)light;
    (void)projection;
    (void)near;
    (void)grid;
    throw NotImplemented("lightTileRange()");
}

TileLightLists buildTileLightLists(const std::vector<LightSphere>& lights, const glm::mat4& projection, float near,
                                   const TileGrid& grid, const std::vector<DepthRange>& tileDepths) {
    // TODO(lab08): for each light, the tiles of lightTileRange() whose depths
    // (tileDepths) its sphere reaches into; count each tile's lights, turn the
    // counts into offsets (a running sum), then fill the lists, lights in
    // increasing order (docs: "Tiled shading", "Depth bounds", TileLightLists in
    // stoa/render/DeferredShading.hpp).
    (void)lights;
    (void)projection;
    (void)near;
    (void)grid;
    (void)tileDepths;
    throw NotImplemented("buildTileLightLists()");
}

} // namespace stoa
