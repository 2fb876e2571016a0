#pragma once
// Lab 09: everything you write (kernel.cpp; the GLSL half is ssao.glsl). docs/labs/09_ssao.md
// derives each function. The lab's app, the tests and later labs include this header; your files
// define what it declares.

#include <stoa/render/AmbientOcclusion.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace stoa {

/// `size` sample offsets (1..kMaxKernelSize) in the unit hemisphere around +z
/// (z >= 0, length <= 1), crowded towards the centre: sample i is scaled by
/// 0.1 + 0.9 (i / size)^2. Drawn from KernelRandom(seed) in the docs' order.
std::vector<glm::vec3> ssaoKernel(int size, std::uint32_t seed);

/// The 4 x 4 tile of random vectors that turns the kernel about the normal,
/// row by row: 16 vectors (x, y, 0), x and y in [-1, 1). From KernelRandom(seed).
std::vector<glm::vec3> ssaoNoise(std::uint32_t seed);

} // namespace stoa
