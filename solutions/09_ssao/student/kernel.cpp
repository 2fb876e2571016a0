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
    KernelRandom random(seed);
    std::vector<glm::vec3> kernel;
    kernel.reserve(static_cast<std::size_t>(size));
    for (int i = 0; i < size; ++i) {
        // A direction in the hemisphere z >= 0, drawn x, y, z in that order (in
        // statements of their own: a constructor's arguments may be evaluated in any order) ...
        const float x = random.next() * 2.0f - 1.0f;
        const float y = random.next() * 2.0f - 1.0f;
        const float z = random.next();
        glm::vec3 sample = glm::normalize(glm::vec3(x, y, z));
        // ... a random length (the fourth number) ...
        sample *= random.next();
        // ... and more of them near the point: 0.1 + 0.9 (i / size)^2.
        const float t = static_cast<float>(i) / static_cast<float>(size);
        sample *= 0.1f + 0.9f * t * t;
        kernel.push_back(sample);
    }
    return kernel;
}

std::vector<glm::vec3> ssaoNoise(std::uint32_t seed) {
    KernelRandom random(seed);
    std::vector<glm::vec3> noise;
    noise.reserve(16);
    for (int i = 0; i < 16; ++i) {
        const float x = random.next() * 2.0f - 1.0f;
        const float y = random.next() * 2.0f - 1.0f;
        noise.emplace_back(x, y, 0.0f);
    }
    return noise;
}

} // namespace stoa
