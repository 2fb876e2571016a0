#pragma once
// What lab 09's functions for screen-space ambient occlusion share with the
// framework (docs/labs/09_ssao.md): the random numbers and the kernel's size
// limit. The functions (the hemisphere of sample offsets, the tile of random
// rotations) are the student's, declared in labs/09_ssao/student/lab09.hpp.
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

} // namespace stoa
