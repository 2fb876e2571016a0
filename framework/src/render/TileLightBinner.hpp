#pragma once
// The framework's own tile assignment of point lights (private to libstoa: no
// public header names it, and it has another shape than any function a
// student writes). DeferredRenderer uses it where DeferredSettings::tileLists
// is TileListSource::Framework (the editor and the showcase, through
// CourseRenderer); a lab's own program keeps the student's function.
//
// What it computes is fixed by the pictures it must not change: the same
// per-tile lists, in the same order (lights in increasing index), as the
// reference assignment of docs/labs/08_deferred.md ("Tiled shading", "Depth
// bounds"): a light's screen rectangle from the eight corners of the box
// around its sphere, and a tile kept where the sphere's span of distances
// meets the tile's depths. TileLightBinnerTests.cpp, with the lab tests of a
// solutions build, compares the two on random scenes. How it gets there differs, for speed: the depths are
// kept as two flat arrays, each light marks one bit per tile it reaches (one
// 64-bit word holds 64 lights; a light's words for a row of tiles lie side by
// side), and each tile's list is read off its bits in order, so that every
// entry is written once, in sequence. How fast:
// tests/benchmarks/light_assignment_benchmark.cpp.

#include <stoa/render/DeferredShading.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace stoa {

class TileLightBinner {
public:
    /// Fills `out` (its buffers are reused from frame to frame) with every
    /// tile's lights: those of `spheres` (view space) whose screen rectangle
    /// under `projection` covers the tile and whose span of distances meets
    /// `depths[tile]`; `near` is the projection's near plane (metres).
    void assign(const std::vector<LightSphere>& spheres, const glm::mat4& projection, float near, const TileGrid& grid,
                const std::vector<DepthRange>& depths, TileLightLists& out);

private:
    // A light's tiles, both ends included, and its span of distances.
    struct Footprint {
        int columnFirst = 0, columnLast = -1, rowFirst = 0, rowLast = -1;
        float nearest = 0.0f, farthest = 0.0f;
    };

    Footprint footprint(const LightSphere& sphere, const glm::mat4& projection, float near, const TileGrid& grid) const;
    // Sets the light's bit in each tile of its rectangle that it reaches; returns how many.
    long markTiles(const Footprint& light, int index, int columns, int tileCount);
    void readLists(int tileCount, int words, long entries, TileLightLists& out) const;

    std::vector<float> m_tileNearest;         // per tile; NaN where the tile is sky
    std::vector<float> m_tileFarthest;
    std::vector<std::uint64_t> m_bits;        // word w of every tile, then word w + 1: bit i of word w is light 64 w + i
};

} // namespace stoa
