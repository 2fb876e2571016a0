#include "Difference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace stoa::grader {

namespace {

constexpr std::array<const char*, 9> kParts = {"top left",    "top",    "top right", "left",        "centre",
                                               "right",       "bottom left", "bottom", "bottom right"};

std::string percent(double share) {
    char text[32];
    if (share >= 0.095) std::snprintf(text, sizeof text, "%.0f%%", 100.0 * share);
    else if (share >= 0.0095) std::snprintf(text, sizeof text, "%.1f%%", 100.0 * share);
    else std::snprintf(text, sizeof text, "%.2f%%", 100.0 * share);
    return text;
}

double luminance(glm::u8vec4 pixel) { return 0.2126 * pixel.r + 0.7152 * pixel.g + 0.0722 * pixel.b; }

} // namespace

std::string describeDifference(const Image& rendered, const Image& reference, const CompareOptions& options) {
    int width = rendered.width(), height = rendered.height();
    if (width != reference.width() || height != reference.height() || width == 0 || height == 0) return "";
    std::array<long, 9> counts{};
    long total = 0;
    double brighter = 0.0;   // summed luminance of yours minus the reference's, over differing pixels
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::u8vec4 a = rendered.pixel(x, y);
            glm::u8vec4 b = reference.pixel(x, y);
            int largest = 0;
            for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
            if (largest <= options.tolerance) continue;
            ++total;
            ++counts[(3 * y / height) * 3 + 3 * x / width];
            brighter += luminance(a) - luminance(b);
        }
    if (total == 0) return "no pixel differs by more than the tolerance without the shift search; "
                           "the difference is faint and spread out";
    std::string text = "differs in " + percent(double(total) / (double(width) * height)) + " of the pixels";
    std::array<int, 9> order{0, 1, 2, 3, 4, 5, 6, 7, 8};
    std::stable_sort(order.begin(), order.end(), [&](int p, int q) { return counts[p] > counts[q]; });
    int partsWithSome = 0;
    for (long count : counts)
        if (count > total / 20) ++partsWithSome;
    std::vector<int> named;
    for (int part : order)
        if (counts[part] * 5 >= total && named.size() < 3) named.push_back(part);
    if (named.empty() || partsWithSome >= 6) {
        text += ", all over the picture";
    } else {
        text += ", most of them in the ";
        for (std::size_t i = 0; i < named.size(); ++i) {
            if (i > 0) text += i + 1 == named.size() ? " and the " : ", the ";
            text += std::string(kParts[named[i]]) + " (" + percent(double(counts[named[i]]) / total) +
                    (i == 0 ? " of them)" : ")");
        }
    }
    double meanShift = brighter / double(total);
    if (meanShift <= -8.0) text += "; darker than the reference there";
    else if (meanShift >= 8.0) text += "; brighter than the reference there";
    return text;
}

} // namespace stoa::grader
