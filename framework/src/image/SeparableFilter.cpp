#include "SeparableFilter.hpp"

#include <stoa/core/Assert.hpp>

#include <algorithm>
#include <cstring>

namespace stoa::detail {

namespace {

// out[x] = sum_t kernel[t] * sources[t][x] for x < count. The sums of a chunk of
// 16 pixels stay in four 4-float vector registers over all taps (GCC's and Clang's
// vector extension; left to itself, GCC at -O2 keeps such sums in memory), then
// a scalar tail. Taps are added in order, as in the tail: no reassociation.
typedef float Float4 __attribute__((vector_size(16)));

inline Float4 load(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

void convolve(float* __restrict out, const float* const* sources, const float* kernel, int taps, int count) {
    int x = 0;
    for (; x + 16 <= count; x += 16) {
        Float4 s0 = {0, 0, 0, 0}, s1 = s0, s2 = s0, s3 = s0;
        for (int t = 0; t < taps; ++t) {
            const float* source = sources[t] + x;
            const float w = kernel[t];
            const Float4 weight = {w, w, w, w};
            s0 += weight * load(source);
            s1 += weight * load(source + 4);
            s2 += weight * load(source + 8);
            s3 += weight * load(source + 12);
        }
        std::memcpy(out + x, &s0, sizeof s0);
        std::memcpy(out + x + 4, &s1, sizeof s1);
        std::memcpy(out + x + 8, &s2, sizeof s2);
        std::memcpy(out + x + 12, &s3, sizeof s3);
    }
    for (; x < count; ++x) {
        float sum = 0.0f;
        for (int t = 0; t < taps; ++t) sum += kernel[t] * sources[t][x];
        out[x] = sum;
    }
}

void checkKernel(const Kernel& kernel) {
    STOA_ASSERT(kernel.size() % 2 == 1, "filterRows(), filterColumns(): the kernel size must be odd (2r+1).");
}

} // namespace

void filterRows(const Plane& in, const Kernel& kernel, Plane& out) {
    checkKernel(kernel);
    const int width = in.width, height = in.height;
    const int radius = static_cast<int>(kernel.size() / 2), taps = static_cast<int>(kernel.size());
    out.width = width;
    out.height = height;
    out.values.resize(in.values.size());
    if (in.values.empty()) return;
    // One row at a time with `radius` copies of its edge pixels on both sides.
    std::vector<float> padded(static_cast<std::size_t>(width) + 2 * radius);
    std::vector<const float*> sources(kernel.size());
    for (int t = 0; t < taps; ++t) sources[t] = padded.data() + t;
    for (int y = 0; y < height; ++y) {
        const float* source = in.row(y);
        std::fill(padded.begin(), padded.begin() + radius, source[0]);
        std::copy(source, source + width, padded.begin() + radius);
        std::fill(padded.begin() + radius + width, padded.end(), source[width - 1]);
        convolve(out.row(y), sources.data(), kernel.data(), taps, width);
    }
}

void filterColumns(const Plane& in, const Kernel& kernel, Plane& out) {
    checkKernel(kernel);
    const int width = in.width, height = in.height;
    const int radius = static_cast<int>(kernel.size() / 2), taps = static_cast<int>(kernel.size());
    out.width = width;
    out.height = height;
    out.values.resize(in.values.size());
    if (in.values.empty()) return;
    std::vector<const float*> sources(kernel.size());
    for (int y = 0; y < height; ++y) {
        for (int t = 0; t < taps; ++t) sources[t] = in.row(std::clamp(y + t - radius, 0, height - 1));
        convolve(out.row(y), sources.data(), kernel.data(), taps, width);
    }
}

} // namespace stoa::detail
