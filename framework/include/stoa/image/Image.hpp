#pragma once
// An 8-bit image in memory, row 0 at the top, 1 to 4 interleaved channels
// (grey, grey+alpha, RGB, RGBA). Needs no GL context.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace stoa {

class Image {
public:
    Image() = default;
    /// A black image (alpha 255 where there is alpha). 0 < channels <= 4.
    Image(int width, int height, int channels = 4);

    /// Limits every image file must keep (Image::load, decode, loadHeightMap):
    /// every use of an image (a texture, a height map, a collision map) goes
    /// through them, and they are checked from the header before anything is
    /// decoded. At maxPixels an 8-bit RGBA PNG decodes in about 0.1 s and
    /// 135 MB at its peak on a 2-core machine (64 MB for the pixels, and
    /// stb_image's buffers while it converts); a 16-bit image counts twice, as
    /// stb_image holds it at 16 bits first. Besides, a small file decodes to
    /// little: its pixels must fit in the file (BMP, TGA, PGM/PPM), in
    /// deflate's best ratio of 1032:1 (PNG), or in the Huffman codes the file
    /// really holds (JPG).
    static constexpr int maxSide = 16384;                      // pixels per side
    static constexpr long long maxPixels = 16LL << 20;         // 16 megapixels (2^24 pixels, 4096 x 4096)
    static constexpr std::size_t maxFileBytes = 256u << 20;    // 256 MiB read at most

    /// Loads PNG, JPG (baseline and progressive), BMP (Windows and OS/2,
    /// uncompressed), TGA, or PGM/PPM (ASCII P2/P3 and binary P5/P6, samples
    /// scaled from 0..maxval to 0..255); 16-bit PNGs and PNMs are read to 8
    /// bits. `desiredChannels` 0 keeps the file's own count; 1..4 converts.
    /// Only a regular file is opened (never a FIFO, a device or a folder),
    /// and at most maxFileBytes are read. Every check happens before
    /// stb_image decodes: the format from the file's first bytes (not its
    /// name: a GIF named .png is refused as a GIF), a size within maxSide and
    /// maxPixels, and data that holds every pixel the header promises (a
    /// truncated or size-patched file is an error, never zero-filled
    /// pixels). Throws InputError naming the file and the cause.
    static Image load(const std::filesystem::path& path, int desiredChannels = 0);

    /// The same for a file already in memory (what load() does after reading
    /// it); `name` is the file named in errors. For tests and fuzzers.
    static Image decode(const std::uint8_t* bytes, std::size_t size, const std::string& name,
                        int desiredChannels = 0);

    /// 8, or 16 for a 16-bit PNG or a PNM with maxval > 255, after the same
    /// header checks as decode() (which throw InputError).
    static int bitsPerChannel(const std::uint8_t* bytes, std::size_t size, const std::string& name);

    /// Writes a PNG. Throws InputError when the file cannot be written.
    void savePng(const std::filesystem::path& path) const;

    int width() const { return m_width; }
    int height() const { return m_height; }
    int channels() const { return m_channels; }
    bool empty() const { return m_pixels.empty(); }
    std::size_t sizeInBytes() const { return m_pixels.size(); }

    std::uint8_t* data() { return m_pixels.data(); }
    const std::uint8_t* data() const { return m_pixels.data(); }

    /// The pixel at (x, y) as RGBA: grey fills r, g and b; missing alpha reads 255.
    glm::u8vec4 pixel(int x, int y) const;          // 0 <= x < width, 0 <= y < height
    /// Writes the channels this image has from an RGBA value (grey takes r).
    void setPixel(int x, int y, glm::u8vec4 rgba);

    /// This image with `channels` channels (grey from RGB uses Rec. 709 luma).
    Image converted(int channels) const;

    /// Turns bottom-up rows (as glReadPixels returns them) into top-down, and back.
    void flipVertically();

private:
    int m_width = 0;
    int m_height = 0;
    int m_channels = 4;
    std::vector<std::uint8_t> m_pixels;
};

} // namespace stoa
