#include <stoa/image/HeightMap.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include "ImageFile.hpp"

#include <stb_image.h>

#include <iostream>
#include <memory>
#include <ostream>
#include <string>

namespace stoa {

namespace {

const char* describeChannels(int channels) {
    switch (channels) {
    case 2: return "grey + alpha";
    case 3: return "RGB";
    default: return "RGBA";
    }
}

} // namespace

HeightSamples loadHeightSamples(const std::filesystem::path& path) {
    const std::string file = readInputFile(path, Image::maxFileBytes, "height map");
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(file.data());
    HeightSamples samples;
    const detail::ImageFileHeader header = detail::checkImageFile(bytes, file.size(), path.string());
    if (header.format == detail::ImageFormat::Pnm) {
        // Stoa's own PNM reader: stb_image leaves 16-bit PNM samples big-endian and unscaled.
        samples.values = detail::decodePgmFractions(bytes, file.size(), path.string(), samples.width, samples.height);
        return samples;
    }
    if (header.format == detail::ImageFormat::Png && header.bitsPerChannel == 16) {
        int channels = 0;
        std::unique_ptr<stbi_us, void (*)(void*)> pixels(
            stbi_load_16_from_memory(bytes, static_cast<int>(file.size()), &samples.width, &samples.height, &channels, 1),
            stbi_image_free);
        if (!pixels) {
            throw InputError(path.string(), 0, std::string("cannot decode the 16-bit PNG: ") +
                                                   (stbi_failure_reason() ? stbi_failure_reason() : "unknown"));
        }
        samples.values.resize(static_cast<std::size_t>(samples.width) * static_cast<std::size_t>(samples.height));
        for (std::size_t i = 0; i < samples.values.size(); ++i) samples.values[i] = pixels.get()[i] / 65535.0f;
        return samples;
    }
    const Image image = Image::decode(bytes, file.size(), path.string(), 1);
    samples.width = image.width();
    samples.height = image.height();
    samples.values.resize(image.sizeInBytes());
    for (std::size_t i = 0; i < samples.values.size(); ++i) samples.values[i] = image.data()[i] / 255.0f;
    return samples;
}

Image loadHeightMap(const std::filesystem::path& path, std::ostream& warnings) {
    // One read of a regular file, with Image's size cap; then the same checks
    // and decode as Image::load().
    const std::string bytes = readInputFile(path, Image::maxFileBytes, "an image file");
    return decodeHeightMap(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path.string(), warnings);
}

Image decodeHeightMap(const std::uint8_t* bytes, std::size_t size, const std::string& name, std::ostream& warnings) {
    // stb_image reads a 16-bit PNG or PGM into 8 bits without a word, so the
    // depth is checked on the header before the image is decoded.
    if (Image::bitsPerChannel(bytes, size, name) == 16) {
        throw InputError(name, 0,
                         "a height map must have 8 bits per pixel; this image has 16. "
                         "Save it as an 8-bit grey image (PGM P5 with maxval 255, or an 8-bit grey PNG)");
    }
    Image image = Image::decode(bytes, size, name);
    if (image.channels() != 1) {
        warnings << "stoa: warning: " << name << ": a height map should be 8-bit grey; this image is "
                 << describeChannels(image.channels()) << ", so its luminance is used as the height\n";
        image = image.converted(1);
    }
    return image;
}

Image loadHeightMap(const std::filesystem::path& path) { return loadHeightMap(path, std::cerr); }

} // namespace stoa
