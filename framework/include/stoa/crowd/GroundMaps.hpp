#pragma once
// The ground a crowd walks on, as two images laid over the scene's footprint
// (lab 10): a collision map (walkable where white) and a height map. A query
// is one texel read (two by four for a bilinear height): the agents know
// nothing of the scene's triangles. No OpenGL here.
//
//        x = footprintMin.x                 x = footprintMax.x
//   z = footprintMin.y  +--------------------------+   image row 0
//                       |  texel (col, row) covers  |
//                       |  [x0, x0 + cellSize.x] x  |
//                       |  [z0, z0 + cellSize.y]    |
//   z = footprintMax.y  +--------------------------+   image row height - 1
//
// Seen from above with +x to the right, +z runs down the image: row 0 is the
// edge at footprintMin.y. The student's look-ups are walkableAt() and
// heightAt() (lab 10's).

#include <stoa/crowd/CrowdWorld.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace stoa {

/// One grid of texels over the footprint, row 0 at z = footprintMin.y.
struct GroundGrid {
    int width = 0;                       // texels along x
    int height = 0;                      // texels along z (image rows)
    glm::vec2 footprintMin{0.0f};        // (x, z) of the grid's corner at texel (0, 0)'s outer corner
    glm::vec2 footprintMax{1.0f};        // (x, z) of the opposite corner
};

/// walkable[row * width + col] is 1 where the image is white (grey >= 128), 0 where it is dark.
struct CollisionMap {
    GroundGrid grid;
    std::vector<std::uint8_t> walkable;
};

/// values[row * width + col] in [0, 1] (grey / 255, or / 65535 for a 16-bit
/// map); the ground there stands heightMin + (heightMax - heightMin) * value
/// metres tall, at the texel's centre.
struct HeightField {
    GroundGrid grid;
    std::vector<float> values;
    float heightMin = 0.0f;
    float heightMax = 0.0f;
};

struct GroundMaps {
    CollisionMap collision;
    HeightField heights;   // a 1 x 1 field of value 0 where the world has no height map (flat at heightMin)
};

/// Reads the maps a world's <ground> names (8-bit images of any kind Image
/// reads, grey or colour as luminance; 16-bit grey PNG or PGM for heights).
/// Throws InputError naming the map's file, or the world file and the
/// <ground> line for a map that is too small (under 2 x 2 texels).
GroundMaps loadGroundMaps(const GroundDescription& ground, const std::filesystem::path& worldFile);

/// A flat, fully walkable ground over [min, max] at height 0 (tests, benchmarks).
GroundMaps flatGround(glm::vec2 footprintMin, glm::vec2 footprintMax, int texels = 64);

/// The height field as a mesh: one vertex at each texel's centre (its height
/// from the field, so a bilinear look-up lies on the mesh's quads up to
/// their bend), two triangles per four neighbouring texels, smooth normals,
/// uvs that repeat every `uvMetres` metres.
Mesh terrainMesh(const HeightField& field, float uvMetres = 4.0f);

} // namespace stoa
