// Lab 09's property checks; see checks.hpp. A kernel drawn in another order is
// still a fine kernel, so the pictures hardly change (by one case's worth);
// but it is not the kernel of the seed, and a kernel built from three draws in
// one expression is a different kernel under another compiler. The expected
// samples below are those of the docs' order, printed by the course's solution.

#include "checks.hpp"
#include "lab09.hpp"

#include <stoa/render/AmbientOcclusion.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace lab09 {

namespace {

std::string vectorText(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6f, %.6f, %.6f)", v.x, v.y, v.z);
    return text;
}

// ssaoKernel(4, 1): the kernel of the seed the graded cases use, four samples.
const glm::vec3 kExpected[] = {{-0.00589053659f, 0.00146378891f, 0.000178154834f},
                               {-0.00685488805f, 0.012752967f, 0.0361817591f},
                               {-0.0505420119f, -0.0281486083f, 0.0127045847f},
                               {-0.0964893475f, 0.260949939f, 0.203060687f}};

// Whether `sample` points where sample `index` of seed 1 would with its first three
// numbers in another order than x, y, z (the three draws in one expression).
bool drawnInAnotherOrder(const glm::vec3& sample, int index) {
    stoa::KernelRandom random(1);
    for (int skip = 0; skip < 4 * index; ++skip) random.next();
    const float u[3] = {random.next(), random.next(), random.next()};
    if (glm::length(sample) < 1e-9f) return false;
    const glm::vec3 direction = glm::normalize(sample);
    int order[3] = {0, 1, 2};
    while (std::next_permutation(order, order + 3)) {   // every order but x, y, z
        const glm::vec3 other(2.0f * u[order[0]] - 1.0f, 2.0f * u[order[1]] - 1.0f, u[order[2]]);
        if (glm::length(direction - glm::normalize(other)) < 1e-4f) return true;
    }
    return false;
}

} // namespace

stoa::CheckResult checkKernelInOrder() {
    const std::vector<glm::vec3> kernel = stoa::ssaoKernel(4, 1);
    if (kernel.size() != 4)
        return stoa::CheckResult::fail("ssaoKernel(4, 1) returned " + std::to_string(kernel.size()) +
                                       " samples, expected 4 (docs: The sample kernel)");
    for (int i = 0; i < 4; ++i) {
        if (glm::length(kernel[i] - kExpected[i]) <= 1e-4f * glm::length(kExpected[i])) continue;
        const std::string found = "ssaoKernel(4, 1): sample " + std::to_string(i) + " is " + vectorText(kernel[i]) +
                                  ", expected " + vectorText(kExpected[i]);
        if (drawnInAnotherOrder(kernel[i], i))
            return stoa::CheckResult::fail(
                found + ": its direction is that of its first three numbers in another order than x, y, z. "
                        "Draw each in a statement of its own: the arguments of one call, such as "
                        "glm::vec3(next(), next(), next()), may be evaluated in any order (docs: The sample kernel)");
        return stoa::CheckResult::fail(found + " (docs: The sample kernel, its four steps)");
    }
    return stoa::CheckResult::pass("the kernel of seed 1 is drawn in the docs' order: x, y, z, then the length");
}

} // namespace lab09
