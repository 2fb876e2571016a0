#pragma once
// Float image planes and separable filtering with clamped borders, for FLIP.
// Internal to stoa_core.

#include <vector>

namespace stoa::detail {

/// One channel of an image, row 0 at the top.
struct Plane {
    int width = 0;
    int height = 0;
    std::vector<float> values;

    Plane() = default;
    Plane(int w, int h) : width(w), height(h), values(static_cast<std::size_t>(w) * h, 0.0f) {}
    float* row(int y) { return values.data() + static_cast<std::size_t>(y) * width; }
    const float* row(int y) const { return values.data() + static_cast<std::size_t>(y) * width; }
};

/// A 1D kernel of odd size 2r+1; tap i weighs the sample at offset i - r.
using Kernel = std::vector<float>;

/// out(x, y) = sum_i kernel[i] * in(clamp(x + i - r), y). `out` is resized to `in`.
void filterRows(const Plane& in, const Kernel& kernel, Plane& out);

/// out(x, y) = sum_i kernel[i] * in(x, clamp(y + i - r)). `out` is resized to `in`.
void filterColumns(const Plane& in, const Kernel& kernel, Plane& out);

} // namespace stoa::detail
