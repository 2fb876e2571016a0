#pragma once
// Lab 09's functions for screen-space ambient occlusion (docs/labs/09_ssao.md):
// the hemisphere of sample offsets and the small tile of random rotations. The
// student defines them in labs/09_ssao/kernel.cpp; the GLSL half is
// labs/09_ssao/ssao.glsl.
//
// Both are seeded through KernelRandom, whose numbers are the same on every
// machine and compiler (std::uniform_real_distribution's are not), so that a
// graded picture depends on the seed alone.

#include <stoa/core/HashRandom.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace stoa {

/// Uniform numbers in [0, 1) from a seed: the "lowbias32" integer hash of a
/// counter that starts from the seed (stoa/core/HashRandom.hpp). Draw them in
/// the order the docs give.
using KernelRandom = HashRandom;

/// The largest kernel the SSAO shader takes (shaders/ssao/ssao.frag's MAX_KERNEL_SIZE).
constexpr int kMaxKernelSize = 64;

// ---- Lab 09's student functions (labs/09_ssao/kernel.cpp) ----------------

/// `size` sample offsets (1..kMaxKernelSize) in the unit hemisphere around +z
/// (z >= 0, length <= 1), crowded towards the centre: sample i is scaled by
/// 0.1 + 0.9 (i / size)^2. Drawn from KernelRandom(seed) in the docs' order.
std::vector<glm::vec3> ssaoKernel(int size, std::uint32_t seed);

/// The 4 x 4 tile of random vectors that turns the kernel about the normal,
/// row by row: 16 vectors (x, y, 0), x and y in [-1, 1). From KernelRandom(seed).
std::vector<glm::vec3> ssaoNoise(std::uint32_t seed);

} // namespace stoa
