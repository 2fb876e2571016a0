#pragma once
// Internal to stoa_core: what an image file's header says, checked before
// stb_image decodes anything, and the PNM (PGM/PPM) decoder Stoa uses instead
// of stb_image's. See Image.hpp for the limits.

#include <stoa/image/Image.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace stoa::detail {

enum class ImageFormat { Png, Jpg, Bmp, Tga, Pnm };

struct ImageFileHeader {
    ImageFormat format = ImageFormat::Png;
    int width = 0;
    int height = 0;
    int bitsPerChannel = 8;  // 16 for 16-bit PNG and PNM with maxval > 255
};

/// Reads and checks the header (and, where it is cheap, the structure) of an
/// image file held in memory: the format from its signature, a size within
/// Image::maxSide and Image::maxPixels, and enough bytes in the file for the
/// pixels the header promises. Throws InputError(name, 0, ...) naming the cause.
ImageFileHeader checkImageFile(const std::uint8_t* bytes, std::size_t size, const std::string& name);

/// Checks that a JPEG's entropy-coded data holds every block its header
/// promises (baseline and extended sequential files: every Huffman code is
/// walked; progressive files: the scans end at an end-of-image marker and
/// hold at least one bit per block). Throws InputError naming the cause.
void checkJpegData(const std::uint8_t* bytes, std::size_t size, const std::string& name);

/// Decodes a PGM or PPM (P2, P3, P5, P6) whose header checkImageFile() has
/// accepted; samples are scaled from 0..maxval to 0..255.
Image decodePnm(const std::uint8_t* bytes, std::size_t size, const std::string& name);

/// The same for a PGM (P2, P5) at full precision: each sample / maxval, in [0, 1].
/// A colour PPM is refused (InputError).
std::vector<float> decodePgmFractions(const std::uint8_t* bytes, std::size_t size, const std::string& name, int& width,
                                      int& height);

} // namespace stoa::detail
