#include <stoa/image/Image.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <stb_image.h>
#include <stb_image_write.h>

namespace stoa {

namespace {

// Channel counts 2 and 4 carry alpha in their last channel.
bool hasAlpha(int channels) { return channels == 2 || channels == 4; }

// Rec. 709 luma, Y = 0.2126 R + 0.7152 G + 0.0722 B, in integer arithmetic
// (the weights scaled by 2^16 sum to exactly 65536, so white stays 255).
std::uint8_t luma(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    const std::uint32_t y = 13933u * r + 46871u * g + 4732u * b;
    return static_cast<std::uint8_t>((y + 32768u) >> 16);
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};

// stb_image reads past the end of a truncated BMP, TGA or PGM/PPM as zeros
// and reports success (PNG and JPG it does catch). completeSize() works out,
// from the header, how many bytes the file needs for the pixels stb decoded,
// so that load() can reject a file that is shorter: 0 when the format is
// another one or its size cannot be known in advance (compressed BMP).

std::uint32_t littleEndian(const std::vector<std::uint8_t>& bytes, std::size_t at, int size) {
    std::uint32_t value = 0;
    for (int i = size - 1; i >= 0; --i) value = (value << 8) | bytes[at + static_cast<std::size_t>(i)];
    return value;
}

std::size_t bmpSize(const std::vector<std::uint8_t>& bytes, int width, int height) {
    if (bytes.size() < 34) return 0;
    const std::uint32_t dataOffset = littleEndian(bytes, 10, 4);
    const std::uint32_t bitsPerPixel = littleEndian(bytes, 28, 2);
    const std::uint32_t compression = littleEndian(bytes, 30, 4);
    if (compression != 0 && compression != 3) return 0;  // RLE: the size depends on the data
    const std::size_t rowBytes = (static_cast<std::size_t>(width) * bitsPerPixel + 31) / 32 * 4;
    return dataOffset + rowBytes * static_cast<std::size_t>(height);
}

/// TGA has no signature; the header is believed when its size matches the decoded one.
std::size_t tgaSize(const std::vector<std::uint8_t>& bytes, int width, int height) {
    if (bytes.size() < 18) return 0;
    const std::uint8_t imageType = bytes[2];
    const bool rle = imageType >= 9 && imageType <= 11;
    if (!rle && (imageType < 1 || imageType > 3)) return 0;
    if (static_cast<int>(littleEndian(bytes, 12, 2)) != width || static_cast<int>(littleEndian(bytes, 14, 2)) != height)
        return 0;
    const std::size_t colourMapBytes = bytes[1] == 1 ? littleEndian(bytes, 5, 2) * ((bytes[7] + 7u) / 8u) : 0;
    const std::size_t pixelBytes = (bytes[16] + 7u) / 8u;
    std::size_t at = 18 + bytes[0] + colourMapBytes;
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (!rle) return at + pixels * pixelBytes;
    // Walk the run-length packets: a header byte, then one pixel (a run) or n raw pixels.
    for (std::size_t done = 0; done < pixels;) {
        if (at >= bytes.size()) return at + 1;  // the next packet header is missing
        const std::uint8_t header = bytes[at++];
        const std::size_t count = (header & 0x7fu) + 1u;
        at += (header & 0x80u) ? pixelBytes : count * pixelBytes;
        done += count;
    }
    return at;
}

/// Binary PGM (P5) and PPM (P6): the header is four tokens, comments allowed,
/// then one whitespace byte before the samples (2 bytes each when maxval > 255).
std::size_t pnmSize(const std::vector<std::uint8_t>& bytes, int width, int height, int channels) {
    std::size_t at = 2;
    unsigned long maxValue = 0;
    for (int token = 0; token < 3; ++token) {
        while (at < bytes.size() && (std::isspace(bytes[at]) || bytes[at] == '#')) {
            if (bytes[at] == '#') {
                while (at < bytes.size() && bytes[at] != '\n') ++at;
            } else {
                ++at;
            }
        }
        unsigned long value = 0;
        while (at < bytes.size() && std::isdigit(bytes[at])) value = value * 10 + (bytes[at++] - '0');
        if (token == 2) maxValue = value;
    }
    const std::size_t sampleBytes = maxValue > 255 ? 2 : 1;
    return at + 1 + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                        static_cast<std::size_t>(channels) * sampleBytes;
}

std::size_t completeSize(const std::vector<std::uint8_t>& bytes, int width, int height, int channels) {
    if (bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M') return bmpSize(bytes, width, height);
    if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '5' || bytes[1] == '6'))
        return pnmSize(bytes, width, height, channels);
    const bool png = bytes.size() >= 4 && bytes[0] == 0x89 && bytes[1] == 'P';
    const bool jpg = bytes.size() >= 2 && bytes[0] == 0xff && bytes[1] == 0xd8;
    if (png || jpg) return 0;  // stb_image checks these itself
    return tgaSize(bytes, width, height);
}

} // namespace

Image::Image(int width, int height, int channels)
    : m_width(width), m_height(height), m_channels(channels) {
    STOA_ASSERT(width >= 0 && height >= 0, "Image::Image(): width and height must not be negative.");
    STOA_ASSERT(channels >= 1 && channels <= 4,
                "Image::Image(): channels must be 1 (grey), 2 (grey+alpha), 3 (RGB) or 4 (RGBA).");
    m_pixels.assign(static_cast<std::size_t>(width) * height * channels, 0);
    if (hasAlpha(channels)) {
        for (std::size_t i = channels - 1; i < m_pixels.size(); i += channels) m_pixels[i] = 255;
    }
}

Image Image::load(const std::filesystem::path& path, int desiredChannels) {
    STOA_ASSERT(desiredChannels >= 0 && desiredChannels <= 4,
                "Image::load(): desiredChannels must be 0 (the file's own) or 1..4.");
    const std::string name = path.string();
    // stb_image opens the file itself and reports a missing file and a folder
    // alike as "can't fopen"; look first, so the message says which it is.
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw InputError(name, 0, "cannot open file: it is a folder, not an image");
    std::vector<std::uint8_t> bytes;
    {
        std::unique_ptr<std::FILE, FileCloser> file(std::fopen(name.c_str(), "rb"));
        if (!file) throw InputError(name, 0, "cannot open file");
        std::uint8_t buffer[1 << 16];
        for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, file.get())) > 0;)
            bytes.insert(bytes.end(), buffer, buffer + got);
        if (std::ferror(file.get())) throw InputError(name, 0, "cannot read file");
    }

    // Decode with the file's own channels and convert here, so that load(path, 1)
    // gives the same grey as converted(1) (stb_image would use Rec. 601 weights).
    int width = 0, height = 0, fileChannels = 0;
    stbi_uc* decoded = bytes.empty() ? nullptr
                                     : stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width,
                                                             &height, &fileChannels, 0);
    if (!decoded) {
        const char* reason = bytes.empty() ? "the file is empty" : stbi_failure_reason();
        throw InputError(name, 0, std::string("not a PNG, BMP, PGM/PPM, TGA or JPG image (stb_image: ") +
                                      (reason ? reason : "unknown error") + ")");
    }
    std::unique_ptr<stbi_uc, void (*)(void*)> owner(decoded, stbi_image_free);
    const std::size_t needed = completeSize(bytes, width, height, fileChannels);
    if (needed > bytes.size()) {
        throw InputError(name, 0, "the file is truncated: its header promises " + std::to_string(width) + "x" +
                                      std::to_string(height) + " pixels, which need " + std::to_string(needed) +
                                      " bytes, but it has " + std::to_string(bytes.size()));
    }

    Image image;
    image.m_width = width;
    image.m_height = height;
    image.m_channels = fileChannels;
    image.m_pixels.assign(decoded, decoded + static_cast<std::size_t>(width) * height * fileChannels);
    if (desiredChannels != 0 && desiredChannels != fileChannels) return image.converted(desiredChannels);
    return image;
}

void Image::savePng(const std::filesystem::path& path) const {
    STOA_ASSERT(!empty(), "Image::savePng(): the image is empty; a PNG needs at least one pixel.");
    const std::string name = path.string();
    const int stride = m_width * m_channels;  // rows are tightly packed
    if (stbi_write_png(name.c_str(), m_width, m_height, m_channels, m_pixels.data(), stride) == 0)
        throw InputError(name, 0, "cannot write PNG");
}

glm::u8vec4 Image::pixel(int x, int y) const {
    STOA_ASSERT(x >= 0 && x < m_width && y >= 0 && y < m_height,
                "Image::pixel(): (x, y) is outside the image; check 0 <= x < width() and 0 <= y < height().");
    const std::uint8_t* p = &m_pixels[(static_cast<std::size_t>(y) * m_width + x) * m_channels];
    switch (m_channels) {
    case 1: return {p[0], p[0], p[0], 255};
    case 2: return {p[0], p[0], p[0], p[1]};
    case 3: return {p[0], p[1], p[2], 255};
    default: return {p[0], p[1], p[2], p[3]};
    }
}

void Image::setPixel(int x, int y, glm::u8vec4 rgba) {
    STOA_ASSERT(x >= 0 && x < m_width && y >= 0 && y < m_height,
                "Image::setPixel(): (x, y) is outside the image; check 0 <= x < width() and 0 <= y < height().");
    std::uint8_t* p = &m_pixels[(static_cast<std::size_t>(y) * m_width + x) * m_channels];
    switch (m_channels) {
    case 1: p[0] = rgba.r; break;
    case 2: p[0] = rgba.r; p[1] = rgba.a; break;
    case 3: p[0] = rgba.r; p[1] = rgba.g; p[2] = rgba.b; break;
    default: p[0] = rgba.r; p[1] = rgba.g; p[2] = rgba.b; p[3] = rgba.a; break;
    }
}

Image Image::converted(int channels) const {
    STOA_ASSERT(channels >= 1 && channels <= 4,
                "Image::converted(): channels must be 1 (grey), 2 (grey+alpha), 3 (RGB) or 4 (RGBA).");
    if (channels == m_channels) return *this;
    Image result(m_width, m_height, channels);
    const std::size_t count = static_cast<std::size_t>(m_width) * m_height;
    const std::uint8_t* source = m_pixels.data();
    std::uint8_t* target = result.m_pixels.data();
    for (std::size_t i = 0; i < count; ++i, source += m_channels, target += channels) {
        // Read as RGBA (grey fills r, g, b; no alpha reads 255), then write.
        std::uint8_t r, g, b, a = 255;
        if (m_channels <= 2) {
            r = g = b = source[0];
            if (m_channels == 2) a = source[1];
        } else {
            r = source[0], g = source[1], b = source[2];
            if (m_channels == 4) a = source[3];
        }
        switch (channels) {
        case 1: target[0] = m_channels <= 2 ? r : luma(r, g, b); break;
        case 2: target[0] = m_channels <= 2 ? r : luma(r, g, b); target[1] = a; break;
        case 3: target[0] = r; target[1] = g; target[2] = b; break;
        default: target[0] = r; target[1] = g; target[2] = b; target[3] = a; break;
        }
    }
    return result;
}

void Image::flipVertically() {
    const std::size_t rowBytes = static_cast<std::size_t>(m_width) * m_channels;
    for (int top = 0, bottom = m_height - 1; top < bottom; ++top, --bottom) {
        std::swap_ranges(m_pixels.begin() + top * rowBytes, m_pixels.begin() + (top + 1) * rowBytes,
                         m_pixels.begin() + bottom * rowBytes);
    }
}

} // namespace stoa
