#pragma once
// Comparison of a rendered image with a reference, tolerant of what differs
// between two correct renders: a few levels of rounding (llvmpipe on another
// CPU) and edges shifted by a pixel. Needs no GL context.
//
// For every pixel, the difference is the smallest per-channel maximum
// |actual - reference| over the reference's (2r+1)x(2r+1) neighbourhood, and
// also over the actual image's neighbourhood (both directions, so a missing
// thin line is not hidden by a neighbour). A pixel is "bad" when that
// difference exceeds `tolerance`. The case passes when the fraction of bad
// pixels is at most `maxBadFraction`.

#include <stoa/image/Image.hpp>

#include <string>

namespace stoa {

struct CompareOptions {
    int tolerance = 12;             // levels (0..255) a pixel may differ after the shift search
    int searchRadius = 1;           // r, in pixels
    double maxBadFraction = 0.002;  // fraction of pixels allowed beyond the tolerance
};

struct CompareResult {
    bool sameSize = false;
    bool passed = false;
    double badFraction = 1.0;       // in [0, 1]
    double meanError = 255.0;       // mean per-pixel difference after the shift search, 0..255
    int maxError = 255;             // largest per-pixel difference after the shift search
    std::string summary;            // one line, e.g. "0.04% pixels off (max 3, mean 0.12)"
};

/// Both images are compared as RGBA. Images of different sizes fail with sameSize false.
CompareResult compareImages(const Image& actual, const Image& reference, const CompareOptions& options = {});

/// A heat map of the shift-tolerant difference: black where equal, through red
/// to yellow where the difference reaches 255; bad pixels at full saturation.
/// Same size as the inputs (which must match).
Image differenceHeatMap(const Image& actual, const Image& reference, const CompareOptions& options = {});

} // namespace stoa
