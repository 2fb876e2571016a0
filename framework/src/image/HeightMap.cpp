#include <stoa/image/HeightMap.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <iostream>
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
