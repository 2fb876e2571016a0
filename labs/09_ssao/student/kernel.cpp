// Lab 09, part 1: the sample kernel and the noise tile, on the CPU. Read
// docs/labs/09_ssao.md, "The sample kernel" and "The noise tile". The app
// uploads them once per case: the kernel as a uniform array (uKernel), the
// noise as a 4 x 4 texture that repeats over the picture (uNoise).

#include "lab09.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/render/AmbientOcclusion.hpp>

#include <glm/glm.hpp>

#include <vector>

namespace stoa {

std::vector<glm::vec3> ssaoKernel(int size, std::uint32_t seed) {
    // TODO(lab09): for each of the `size` samples, four numbers from
    // KernelRandom random(seed), in this order: x and y in [-1, 1), z in [0, 1);
    // normalise; times the fourth number; times 0.1 + 0.9 (i / size)^2
    // (docs: "The sample kernel"). Draw each number in a statement of its own:
    // C++ may evaluate a constructor's arguments in any order.
    (void)size;
    (void)seed;
    throw NotImplemented("ssaoKernel()");
}

std::vector<glm::vec3> ssaoNoise(std::uint32_t seed) {
    // TODO(lab09): 16 vectors (x, y, 0), x then y drawn from KernelRandom(seed)
    // and mapped to [-1, 1) (docs: "The noise tile").
    (void)seed;
    throw NotImplemented("ssaoNoise()");
}

} // namespace stoa
