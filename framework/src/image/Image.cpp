#include <stoa/image/Image.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include "ImageFile.hpp"

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
    const std::string bytes = readInputFile(path, maxFileBytes, "an image file");
    return decode(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path.string(), desiredChannels);
}

Image Image::decode(const std::uint8_t* bytes, std::size_t size, const std::string& name, int desiredChannels) {
    STOA_ASSERT(desiredChannels >= 0 && desiredChannels <= 4,
                "Image::decode(): desiredChannels must be 0 (the file's own) or 1..4.");
    if (size > maxFileBytes) {
        throw InputError(name, 0, "the image is too large: " + std::to_string(size) + " bytes, past the limit of " +
                                      std::to_string(maxFileBytes) + " bytes");
    }
    // Sizes and structure first: stb_image sees only files whose header is
    // within the limits and whose data can hold the pixels it promises.
    const detail::ImageFileHeader header = detail::checkImageFile(bytes, size, name);
    if (header.format == detail::ImageFormat::Jpg) detail::checkJpegData(bytes, size, name);

    Image image;
    if (header.format == detail::ImageFormat::Pnm) {
        image = detail::decodePnm(bytes, size, name);
    } else {
        // Decode with the file's own channels and convert here, so that load(path, 1)
        // gives the same grey as converted(1) (stb_image would use Rec. 601 weights).
        int width = 0, height = 0, fileChannels = 0;
        stbi_uc* decoded =
            stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &fileChannels, 0);
        if (!decoded) {
            const char* reason = stbi_failure_reason();
            throw InputError(name, 0, std::string("the image data is damaged (stb_image: ") +
                                          (reason && *reason ? reason : "no reason given") + ")");
        }
        std::unique_ptr<stbi_uc, void (*)(void*)> owner(decoded, stbi_image_free);
        if (width != header.width || height != header.height || fileChannels < 1 || fileChannels > 4) {
            throw InputError(name, 0, "the image decoded to " + std::to_string(width) + "x" + std::to_string(height) +
                                          " pixels, but its header promises " + std::to_string(header.width) +
                                          "x" + std::to_string(header.height));
        }
        image.m_width = width;
        image.m_height = height;
        image.m_channels = fileChannels;
        image.m_pixels.assign(decoded, decoded + static_cast<std::size_t>(width) * height * fileChannels);
    }
    if (desiredChannels != 0 && desiredChannels != image.m_channels) return image.converted(desiredChannels);
    return image;
}

int Image::bitsPerChannel(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    return detail::checkImageFile(bytes, size, name).bitsPerChannel;
}

void Image::savePng(const std::filesystem::path& path) const {
    STOA_ASSERT(!empty(), "Image::savePng(): the image is empty; a PNG needs at least one pixel.");
    const std::string name = path.string();
    const int stride = m_width * m_channels;  // rows are tightly packed
    if (stbi_write_png(name.c_str(), m_width, m_height, m_channels, m_pixels.data(), stride) == 0) {
        // stb_image_write says only that it failed: find why, as the user would.
        std::error_code error;
        const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
        std::string why = "the file cannot be created or written (no permission, or the disk is full?)";
        if (!std::filesystem::exists(folder, error)) why = "its folder " + folder.string() + " does not exist";
        else if (!std::filesystem::is_directory(folder, error)) why = folder.string() + " is not a folder";
        else if (std::filesystem::is_directory(path, error)) why = "a folder of that name is in the way";
        throw InputError(name, 0, "cannot write the PNG: " + why);
    }
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
