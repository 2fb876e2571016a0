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
//
// Then the perceptual error: LDR-FLIP (see Flip.hpp), whose mean must be at most
// `maxFlipMean`. The gate catches what differs in a few pixels; FLIP what is
// small per pixel but visible over an area (a slightly wrong shade everywhere).
// Fast path: identical images, and images whose shift-tolerant difference is
// nowhere above the tolerance (the floor), skip FLIP and count as FLIP mean 0.

#include <stoa/image/Image.hpp>

#include <vector>

#include <string>

namespace stoa {

struct CompareOptions {
    int tolerance = 12;             // levels (0..255) a pixel may differ after the shift search
    int searchRadius = 1;           // r, in pixels
    double maxBadFraction = 0.002;  // fraction of pixels allowed beyond the tolerance
    double maxFlipMean = 0.05;      // largest mean LDR-FLIP error that passes; above what a
                                    // one-pixel shift of a whole reference gives (up to 0.028).
                                    // docs/instructor-guide.md, "Calibration and margins"
};

struct CompareResult {
    bool sameSize = false;
    bool passed = false;
    double badFraction = 1.0;       // in [0, 1]
    double meanError = 255.0;       // mean per-pixel difference after the shift search, 0..255
    int maxError = 255;             // largest per-pixel difference after the shift search
    double flipMean = -1.0;         // mean LDR-FLIP error in [0, 1]; 0 on the fast path, -1 when
                                    // not computed (images of different sizes)
    std::vector<float> flipErrorMap;  // FLIP's per-pixel error when it ran, else empty
    std::string summary;            // one line, e.g. "0.04% of pixels beyond tolerance 12 (max 3,
                                    // mean 0.12), FLIP mean 0.0123"
};

/// Both images are compared as RGBA (FLIP as RGB). Images of different sizes fail
/// with sameSize false. Passes when the gate passes and flipMean <= maxFlipMean.
CompareResult compareImages(const Image& actual, const Image& reference, const CompareOptions& options = {});

/// A heat map of the difference, same size as the inputs (which must match).
/// Where FLIP runs (the images differ beyond the tolerance somewhere): FLIP's
/// heat map (FlipResult::heatMap()). On the fast path: the shift-tolerant
/// difference, black where equal, dark red up to the tolerance.
Image differenceHeatMap(const Image& actual, const Image& reference, const CompareOptions& options = {});

/// The same heat map from a result compareImages() already computed for these
/// images and options, without running FLIP again.
Image differenceHeatMap(const Image& actual, const Image& reference, const CompareResult& computed,
                        const CompareOptions& options = {});

} // namespace stoa
