#pragma once
// The heat map's colour legend: the colours a failed case's heat map uses
// (FLIP's per-pixel error through its colour map, stoa/image/Flip.hpp), from 0
// (no visible difference) on the left to 1 (the largest) on the right.
// `stoa-grade --write-heatmap-legend FILE` writes it; docs/images/heatmap-legend.png
// is that picture (a test checks it), and the HTML report draws the same colours.

#include <stoa/image/Image.hpp>

#include <filesystem>
#include <string>

namespace stoa::grader {

/// 512 x 40 RGBA: the colour of error x / 511 in column x, with a short grey tick
/// at 0, 0.25, 0.5, 0.75 and 1 along the bottom 8 rows.
Image heatMapLegend();

/// A CSS linear-gradient() of the same colours (for the HTML report).
std::string heatMapLegendGradient();

/// Writes heatMapLegend() as a PNG. Throws InputError when it cannot be written.
void writeHeatMapLegend(const std::filesystem::path& path);

} // namespace stoa::grader
