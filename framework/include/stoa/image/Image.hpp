#pragma once
// An 8-bit image in memory, row 0 at the top, 1 to 4 interleaved channels
// (grey, grey+alpha, RGB, RGBA). Needs no GL context.

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec4.hpp>

namespace stoa {

class Image {
public:
    Image() = default;
    /// A black image (alpha 255 where there is alpha). 0 < channels <= 4.
    Image(int width, int height, int channels = 4);

    /// Loads PNG, BMP, PGM/PPM, TGA or JPG through stb_image. `desiredChannels`
    /// 0 keeps the file's own count; 1..4 converts. Throws InputError naming the
    /// file and stb's reason when the file is missing or does not decode, and
    /// when an uncompressed BMP, a TGA or a binary PGM/PPM is shorter than its
    /// header promises (stb_image would fill the missing pixels with zeros).
    static Image load(const std::filesystem::path& path, int desiredChannels = 0);

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
