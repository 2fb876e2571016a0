#pragma once
// Loading the height maps that bump mapping turns into normal maps (lab 04):
// one 8-bit grey channel, 0 = lowest, 255 = highest, row 0 at the top of the
// image. Needs no GL context.
//
//   Image height = loadHeightMap(assetsDir() / "acropolis/wall_height.pgm");
//   Image normals = normalMapFromHeight(height, 4.0f);   // lab 04's student code

#include <stoa/image/Image.hpp>

#include <filesystem>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace stoa {

/// Loads a height map from a PGM (P2/P5), PNG, BMP, TGA or JPG file and returns
/// it as a 1-channel Image, with Image::load()'s checks and limits (a regular
/// file only, at most Image::maxFileBytes read, Image::maxSide pixels per side,
/// Image::maxPixels in all). What the file holds decides what happens:
///   - 8-bit grey: returned as it is;
///   - 8-bit grey + alpha, RGB or RGBA: the documented fallback. The height is
///     the colour's luminance (Rec. 709 weights, alpha ignored) and one line
///     on `warnings` names the file and says so, because a colour picture is
///     more often the wrong file (the diffuse map) than a height map;
///   - 16 bits per channel: InputError naming the file (Stoa's height maps are
///     8-bit; rescaling silently would change the bump strength);
///   - missing, a folder, a FIFO or device, a symbolic link loop, a name too
///     long, not an image, damaged or truncated: InputError naming the file
///     and the cause (never std::filesystem::filesystem_error).
Image loadHeightMap(const std::filesystem::path& path, std::ostream& warnings);
/// The same for a file already in memory; `name` is the file named in errors.
/// For tests and fuzzers.
Image decodeHeightMap(const std::uint8_t* bytes, std::size_t size, const std::string& name, std::ostream& warnings);
/// The same, warnings on std::cerr.
Image loadHeightMap(const std::filesystem::path& path);

/// A height map at full precision, for ground that agents stand on (lab 10's
/// GroundMaps): values[row * width + col] in [0, 1], row 0 at the top.
struct HeightSamples {
    int width = 0;
    int height = 0;
    std::vector<float> values;
};

/// Loads a height map keeping every bit: a 16-bit grey PNG as value / 65535,
/// a PGM (P2, P5; 8 or 16 bits) as sample / maxval, any other 8-bit image
/// Image::load() reads as its luminance / 255 (no warning: a ground map may be
/// drawn in colour). The same checks and limits as Image::load(); InputError
/// naming the file and the cause.
HeightSamples loadHeightSamples(const std::filesystem::path& path);

} // namespace stoa
