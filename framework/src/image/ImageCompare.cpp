#include <stoa/image/ImageCompare.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/image/Flip.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace stoa {

namespace {

// Both images as RGBA, without a copy when they already are.
class RgbaView {
public:
    explicit RgbaView(const Image& image) {
        if (image.channels() == 4) {
            m_data = image.data();
        } else {
            m_converted = image.converted(4);
            m_data = m_converted.data();
        }
    }
    const std::uint8_t* data() const { return m_data; }

private:
    Image m_converted;
    const std::uint8_t* m_data = nullptr;
};

// The shift search reads every pixel 2 x (2r+1)^2 times, so its data layout is
// chosen for speed. Each row is split into four planes (R, G, B, A) of bytes, so
// that one loop over a row handles one channel of many pixels at once (the
// compiler turns it into SIMD instructions). Each plane row has `radius` extra
// pixels on both sides that repeat the edge pixel, and rows above and below the
// image repeat the edge row, so no neighbour lookup needs a bounds check. This
// changes no result: a repeated pixel also lies inside the clipped window, and
// a minimum does not change when a candidate appears twice. Row lengths are
// padded to whole chunks of kChunk pixels.
constexpr int kChunk = 32;

// The rows of one image in that layout, built on demand into 2r+1 slots: the
// search around row y needs rows y-r..y+r only, and rows far from any
// difference are never built at all.
class PlaneRows {
public:
    PlaneRows(const std::uint8_t* rgba, int width, int height, int radius, int paddedWidth)
        : m_rgba(rgba), m_width(width), m_height(height), m_radius(radius), m_paddedWidth(paddedWidth),
          m_stride(paddedWidth + 2 * radius), m_slotRows(2 * radius + 1, -1),
          m_bytes(static_cast<std::size_t>(m_slotRows.size()) * 4 * m_stride) {}

    /// Pixel x = 0 of one channel of row y (clamped to the image); the row may be
    /// read from x = -radius to paddedWidth + radius.
    const std::uint8_t* row(int channel, int y) {
        y = std::clamp(y, 0, m_height - 1);
        const std::size_t slot = static_cast<std::size_t>(y) % m_slotRows.size();
        if (m_slotRows[slot] != y) build(slot, y);
        return m_bytes.data() + (slot * 4 + channel) * m_stride + m_radius;
    }

private:
    void build(std::size_t slot, int y) {
        const std::uint8_t* source = m_rgba + static_cast<std::size_t>(y) * m_width * 4;
        for (int channel = 0; channel < 4; ++channel) {
            std::uint8_t* target = m_bytes.data() + (slot * 4 + channel) * m_stride + m_radius;
            for (int x = 0; x < m_width; ++x) target[x] = source[4 * x + channel];
            std::fill(target - m_radius, target, target[0]);
            std::fill(target + m_width, target + m_paddedWidth + m_radius, target[m_width - 1]);
        }
        m_slotRows[slot] = y;
    }

    const std::uint8_t* m_rgba;
    int m_width, m_height, m_radius, m_paddedWidth, m_stride;
    std::vector<int> m_slotRows;  // which image row each slot holds, -1 for none
    std::vector<std::uint8_t> m_bytes;
};

// By value and branch-free, unlike std::max on references, which the vectoriser
// of GCC 12 at -O2 gives up on ("control flow in loop").
inline std::uint8_t larger(std::uint8_t a, std::uint8_t b) { return a > b ? a : b; }
inline std::uint8_t smaller(std::uint8_t a, std::uint8_t b) { return a < b ? a : b; }
inline std::uint8_t absoluteDifference(std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(larger(a, b) - smaller(a, b));
}

// best[x] = min(best[x], max over the channels of |from[c][x] - to[c][x]|) for one
// shift of a whole row. `count` is a multiple of kChunk; the fixed inner trip
// count and the restrict pointers are what let the compiler vectorise at -O2.
void accumulateShift(const std::uint8_t* __restrict from0, const std::uint8_t* __restrict from1,
                     const std::uint8_t* __restrict from2, const std::uint8_t* __restrict from3,
                     const std::uint8_t* __restrict to0, const std::uint8_t* __restrict to1,
                     const std::uint8_t* __restrict to2, const std::uint8_t* __restrict to3,
                     std::uint8_t* __restrict best, int count) {
    for (int start = 0; start < count; start += kChunk) {
        for (int i = start; i < start + kChunk; ++i) {
            const std::uint8_t difference =
                larger(larger(absoluteDifference(from0[i], to0[i]), absoluteDifference(from1[i], to1[i])),
                       larger(absoluteDifference(from2[i], to2[i]), absoluteDifference(from3[i], to3[i])));
            best[i] = smaller(best[i], difference);
        }
    }
}

// One direction of the shift search for row y: for every pixel p of `from`,
//   best(p) = min over q in the (2r+1)x(2r+1) window around p (clipped to the image)
//             of max over the four channels of |from(p) - to(q)|.
void searchRow(PlaneRows& from, PlaneRows& to, int y, int radius, int paddedWidth, std::uint8_t* best) {
    std::fill(best, best + paddedWidth, std::uint8_t(255));
    const std::uint8_t* f[4] = {from.row(0, y), from.row(1, y), from.row(2, y), from.row(3, y)};
    for (int dy = -radius; dy <= radius; ++dy) {
        const std::uint8_t* t[4] = {to.row(0, y + dy), to.row(1, y + dy), to.row(2, y + dy), to.row(3, y + dy)};
        for (int dx = -radius; dx <= radius; ++dx)
            accumulateShift(f[0], f[1], f[2], f[3], t[0] + dx, t[1] + dx, t[2] + dx, t[3] + dx, best, paddedWidth);
    }
}

// The shift-tolerant difference of every pixel (0..255), row 0 at the top.
// Searching from both sides matters: a thin line the actual image lacks is
// close to a matching background pixel of the reference, so actual -> reference
// alone would miss it, while reference -> actual finds no line pixel nearby.
std::vector<std::uint8_t> differenceMap(const Image& actual, const Image& reference, int radius) {
    const int width = actual.width(), height = actual.height();
    std::vector<std::uint8_t> result(static_cast<std::size_t>(width) * height, 0);
    if (result.empty()) return result;
    const RgbaView a(actual), r(reference);
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
    const int paddedWidth = (width + kChunk - 1) / kChunk * kChunk;
    PlaneRows rowsA(a.data(), width, height, radius, paddedWidth);
    PlaneRows rowsR(r.data(), width, height, radius, paddedWidth);
    std::vector<std::uint8_t> forward(paddedWidth), backward(paddedWidth);
    for (int y = 0; y < height; ++y) {
        // Where both rows are equal every difference is 0 (q = p is in the window).
        if (std::memcmp(a.data() + y * rowBytes, r.data() + y * rowBytes, rowBytes) == 0) continue;
        searchRow(rowsA, rowsR, y, radius, paddedWidth, forward.data());
        searchRow(rowsR, rowsA, y, radius, paddedWidth, backward.data());
        std::uint8_t* out = result.data() + static_cast<std::size_t>(y) * width;
        for (int x = 0; x < width; ++x) out[x] = larger(forward[x], backward[x]);
    }
    return result;
}

void checkOptions(const CompareOptions& options) {
    STOA_ASSERT(options.searchRadius >= 0 && options.searchRadius <= 16,
                "compareImages(), differenceHeatMap(): CompareOptions::searchRadius must be 0..16 pixels.");
    STOA_ASSERT(options.tolerance >= 0 && options.tolerance <= 255,
                "compareImages(), differenceHeatMap(): CompareOptions::tolerance must be 0..255 levels.");
    STOA_ASSERT(options.maxBadFraction >= 0.0 && options.maxBadFraction <= 1.0,
                "compareImages(), differenceHeatMap(): CompareOptions::maxBadFraction must be in [0, 1].");
    STOA_ASSERT(options.maxFlipMean >= 0.0 && options.maxFlipMean <= 1.0,
                "compareImages(), differenceHeatMap(): CompareOptions::maxFlipMean must be in [0, 1].");
}

// The shift-tolerant difference as a heat map (the fast path's picture).
Image shiftHeatMap(const std::vector<std::uint8_t>& difference, int width, int height, int tolerance) {
    Image heat(width, height, 4);
    std::uint8_t* out = heat.data();
    for (std::size_t i = 0; i < difference.size(); ++i, out += 4) {
        const int d = difference[i];
        if (d <= tolerance) {
            // Within the tolerance: a dark red that reaches half brightness at the tolerance,
            // so accepted rounding shows without drawing the eye.
            out[0] = static_cast<std::uint8_t>(tolerance == 0 ? 0 : (128 * d) / tolerance);
        } else {
            // Bad: full red, turning yellow as the difference grows to 255.
            out[0] = 255;
            out[1] = static_cast<std::uint8_t>(255 * (d - tolerance) / (255 - tolerance));
        }
        out[3] = 255;
    }
    return heat;
}

std::string formatPercent(double fraction) {
    const double percent = fraction * 100.0;
    char text[32];
    // Two decimals, except that a handful of bad pixels must not read as "0.00%".
    if (percent > 0.0 && percent < 0.01) std::snprintf(text, sizeof text, "%.2g%%", percent);
    else std::snprintf(text, sizeof text, "%.2f%%", percent);
    return text;
}

} // namespace

CompareResult compareImages(const Image& actual, const Image& reference, const CompareOptions& options) {
    checkOptions(options);
    CompareResult result;
    if (actual.width() != reference.width() || actual.height() != reference.height()) {
        result.summary = "size " + std::to_string(actual.width()) + "x" + std::to_string(actual.height()) +
                         " differs from the reference's " + std::to_string(reference.width()) + "x" +
                         std::to_string(reference.height());
        return result;
    }
    result.sameSize = true;

    if (actual.sizeInBytes() == 0 || (actual.channels() == reference.channels() &&
                                      std::memcmp(actual.data(), reference.data(), actual.sizeInBytes()) == 0)) {
        // The common case of a correct render on the machine that made the reference.
        result.badFraction = 0.0;
        result.meanError = 0.0;
        result.maxError = 0;
        result.flipMean = 0.0;
    } else {
        const std::vector<std::uint8_t> difference = differenceMap(actual, reference, options.searchRadius);
        std::size_t bad = 0;
        std::uint64_t sum = 0;
        std::uint8_t largest = 0;
        for (const std::uint8_t d : difference) {
            bad += d > options.tolerance;
            sum += d;
            largest = larger(largest, d);
        }
        const double count = static_cast<double>(difference.size());
        result.badFraction = bad / count;
        result.meanError = sum / count;
        result.maxError = largest;
        if (largest <= options.tolerance) {
            // Nothing beyond the floor anywhere: rounding only, FLIP would see nothing.
            result.flipMean = 0.0;
        } else {
            FlipResult flip = computeFlip(actual, reference);
            result.flipMean = flip.mean;
            result.flipErrorMap = std::move(flip.errorMap);
        }
    }
    result.passed = result.badFraction <= options.maxBadFraction && result.flipMean <= options.maxFlipMean;

    char tail[128];
    std::snprintf(tail, sizeof tail, " of pixels beyond tolerance %d (max %d, mean %.2f), FLIP mean %.4f",
                  options.tolerance, result.maxError, result.meanError, result.flipMean);
    result.summary = formatPercent(result.badFraction) + tail;
    return result;
}

Image differenceHeatMap(const Image& actual, const Image& reference, const CompareResult& computed,
                        const CompareOptions& options) {
    checkOptions(options);
    STOA_ASSERT(actual.width() == reference.width() && actual.height() == reference.height(),
                "differenceHeatMap(): the images differ in size; check CompareResult::sameSize first.");
    if (!computed.flipErrorMap.empty()) {
        STOA_ASSERT(computed.flipErrorMap.size() == static_cast<std::size_t>(actual.width()) * actual.height(),
                    "differenceHeatMap(): the CompareResult belongs to images of another size.");
        FlipResult flip;
        flip.width = actual.width();
        flip.height = actual.height();
        flip.errorMap = computed.flipErrorMap;
        return flip.heatMap();
    }
    const std::vector<std::uint8_t> difference = differenceMap(actual, reference, options.searchRadius);
    return shiftHeatMap(difference, actual.width(), actual.height(), options.tolerance);
}

Image differenceHeatMap(const Image& actual, const Image& reference, const CompareOptions& options) {
    checkOptions(options);
    STOA_ASSERT(actual.width() == reference.width() && actual.height() == reference.height(),
                "differenceHeatMap(): the images differ in size; check CompareResult::sameSize first.");
    const std::vector<std::uint8_t> difference = differenceMap(actual, reference, options.searchRadius);
    std::uint8_t largest = 0;
    for (const std::uint8_t d : difference) largest = larger(largest, d);
    if (largest > options.tolerance) return computeFlip(actual, reference).heatMap();
    return shiftHeatMap(difference, actual.width(), actual.height(), options.tolerance);
}

} // namespace stoa
