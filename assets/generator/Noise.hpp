#pragma once
// Deterministic randomness for the generated assets: an integer hash and value
// noise built on it. Nothing here reads a clock or a global seed, so the same
// arguments give the same bits on every run (the committed files depend on it).

#include <cstdint>

namespace stoa::assets {

/// Mixes 32 bits so that neighbouring inputs give unrelated outputs.
std::uint32_t hash32(std::uint32_t x);
/// A hash of a lattice point and a seed, as a float in [0, 1).
float hashToUnit(int x, int y, int z, std::uint32_t seed);

/// Smooth value noise in [0, 1) at (x, y), in lattice cells. The lattice repeats
/// every `period` cells along x and y (period > 0), so a texture sampled over
/// exactly `period` cells tiles without a seam.
float tiledNoise(float x, float y, int period, std::uint32_t seed);
/// Sum of `octaves` tiledNoise layers, each at twice the frequency (and period)
/// and half the weight of the last; normalized back to [0, 1).
float tiledFbm(float x, float y, int period, int octaves, std::uint32_t seed);

/// Smooth value noise in [0, 1) in 3D (no repetition), for displacing meshes.
float noise3(float x, float y, float z, std::uint32_t seed);
/// Fractal sum of noise3, normalized to [0, 1).
float fbm3(float x, float y, float z, int octaves, std::uint32_t seed);

} // namespace stoa::assets
