#pragma once
// LDR-FLIP, the perceptual difference of Andersson et al. 2020, "FLIP: A
// Difference Evaluator for Alternating Images" (HPG 2020), for 8-bit sRGB
// images. Needs no GL context.
//
// The pipeline, as the paper describes it:
//   colour   sRGB -> linear RGB -> XYZ -> YCxCz (an opponent space, linear in XYZ);
//            each channel filtered with its contrast-sensitivity filter (a sum of
//            Gaussians whose width in pixels follows from the pixels per degree);
//            back to linear RGB, clamped to [0, 1] -> CIELAB -> Hunt adjustment
//            (a*, b* scaled by 0.01 L*); HyAB distance |dL| + |(da, db)|, raised to
//            qc = 0.7 and mapped to [0, 1] (below pc = 0.4 of the largest error,
//            green against blue, linearly to [0, pt = 0.95], above it to (0.95, 1]).
//   features the luminance Y/Yn of the unfiltered images is filtered with first
//            (edges) and second (points) derivatives of a Gaussian of standard
//            deviation 0.5 x 0.082 degrees; the feature difference is
//            (max(|edge_t - edge_r|, |point_t - point_r|) / sqrt 2)^qf, qf = 0.5.
//   error    colourError^(1 - featureError), per pixel, in [0, 1].
// All filters are separable and clamp at the borders. Alpha is ignored (the
// shift-tolerant gate of compareImages() checks it). FLIP is not symmetric:
// the reference is the second argument.

#include <stoa/image/Image.hpp>

#include <cstdint>
#include <vector>

namespace stoa {

struct FlipOptions {
    /// Pixels per degree of visual angle of the observer. 67 is the paper's
    /// default set-up: a 0.7 m wide 3840-pixel monitor seen from 0.7 m.
    double pixelsPerDegree = 67.0;
};

struct FlipResult {
    double mean = 0.0;               // mean of errorMap, in [0, 1]
    std::vector<float> errorMap;     // width x height errors in [0, 1], row 0 at the top
    int width = 0;
    int height = 0;

    /// The error map through a magma-like colour map (black-purple for 0, through
    /// red and orange, to pale yellow for 1), as RGBA with alpha 255.
    Image heatMap() const;
};

/// FLIP of `test` against `reference`. Both must have the same size (STOA_ASSERT);
/// any channel count is read as RGB. An empty image gives mean 0 and an empty map.
FlipResult computeFlip(const Image& test, const Image& reference, const FlipOptions& options = {});

/// The colour of `error` (clamped to [0, 1]) in the heat map's colour map, as 8-bit RGB.
void flipHeatColor(float error, std::uint8_t rgb[3]);

} // namespace stoa
