#pragma once
// Making the ground maps of the example worlds (assets/crowds/): a collision
// map from the Acropolis's own triangles, and the rolling hills of the
// predators-and-prey world. `stoa-crowds --make-maps DIR` writes them; the
// tests check that the committed files are what it writes.

#include <stoa/crowd/GroundMaps.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/scene/AcropolisScene.hpp>

#include <filesystem>
#include <vector>

namespace stoa {

/// A grey collision map over `grid`: black where a piece's surface passes
/// between heights minY and maxY (what an agent would walk into), and within
/// `clearance` metres of that; white elsewhere. Pieces named "floor" are skipped.
Image collisionMapFromPieces(const std::vector<AcropolisPiece>& pieces, const GroundGrid& grid, float minY,
                             float maxY, float clearance);

/// Rolling hills, `size` x `size` texels, 8-bit grey: a sum of smooth bumps
/// and hollows at seeded places, the lowest texel 0 and the highest 255.
Image hillsHeightMap(int size, std::uint32_t seed);

/// Walkable except where the ground lies below `waterLevel` (0..1 of the
/// height map: ponds) or rises more than `maxSlope` (metres per metre) between
/// neighbours, for heights spanning `heightRange` metres over `grid`.
Image hillsCollisionMap(const Image& heights, const GroundGrid& grid, float heightRange, float waterLevel,
                        float maxSlope);

/// Writes acropolis_collision.png, hills_height.png and hills_collision.png to
/// `folder`; returns the paths written.
std::vector<std::filesystem::path> writeExampleGroundMaps(const std::filesystem::path& folder);

} // namespace stoa
