#pragma once
// The types of lab 08's functions for deferred shading (docs/labs/08_deferred.md):
// screen tiles, lights as spheres, depth ranges and the tiles' light lists. The
// functions (how far a point light reaches, the light-volume pass's state, which
// tiles each light touches) are the student's, declared in
// labs/08_deferred/student/lab08.hpp; DeferredRenderer reaches them through the
// framework's student-code table (StudentCode::deferred).
//
// Tiles count from the bottom-left corner of the picture, as gl_FragCoord
// does: tile (0, 0) holds pixels x, y in [0, tileSize).

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace stoa {

struct PointLight;
struct RenderState;

/// The picture cut into square tiles of `tileSize` pixels; the last column
/// and row may be cut short by the picture's edge.
struct TileGrid {
    glm::ivec2 viewport{1};   // the picture, pixels
    int tileSize = 16;        // pixels

    glm::ivec2 tiles() const { return (viewport + glm::ivec2(tileSize - 1)) / tileSize; }
    int tileCount() const { return tiles().x * tiles().y; }
    /// The index of tile (column, row): row * tiles().x + column.
    int index(glm::ivec2 tile) const { return tile.y * tiles().x + tile.x; }
};

/// The tiles a light can touch: columns first.x..last.x and rows
/// first.y..last.y, both ends included. Empty when last < first on an axis.
struct TileRange {
    glm::ivec2 first{0};
    glm::ivec2 last{-1};
    bool empty() const { return last.x < first.x || last.y < first.y; }
};

/// A point light as the tiled pass sees it: its centre in view space (the
/// camera at the origin looking down -z) and its reach (lightReach()).
struct LightSphere {
    glm::vec3 centerView{0.0f};
    float reach = 0.0f;
};

/// The depths a tile's pixels see, as distances in front of the camera
/// (metres along -z in view space): the nearest and the farthest surface the
/// G-buffer holds in the tile. Empty (nearest > farthest) where the tile shows
/// only sky.
struct DepthRange {
    float nearest = 1.0f;
    float farthest = 0.0f;
    bool empty() const { return nearest > farthest; }
};

/// For every tile, the lights that can reach it: tile t's lights are
/// lights[offsets[t]] .. lights[offsets[t + 1] - 1], indices into the list
/// buildTileLightLists() was given, in increasing order.
struct TileLightLists {
    TileGrid grid;
    std::vector<int> offsets;   // grid.tileCount() + 1 entries, offsets[0] = 0
    std::vector<int> lights;
};

} // namespace stoa
