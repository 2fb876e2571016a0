#include <stoa/image/HeightMap.hpp>

#include <stoa/core/InputError.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <ostream>
#include <string>

#include <stb_image.h>

namespace stoa {

namespace {

// stb_image reads a 16-bit PNG or PGM into 8 bits without a word, so the depth
// is checked on the file before Image::load() decodes it.
bool isSixteenBit(const std::filesystem::path& path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.string().c_str(), "rb"), std::fclose);
    return file && stbi_is_16_bit_from_file(file.get()) != 0;
}

const char* describeChannels(int channels) {
    switch (channels) {
    case 2: return "grey + alpha";
    case 3: return "RGB";
    default: return "RGBA";
    }
}

} // namespace

Image loadHeightMap(const std::filesystem::path& path, std::ostream& warnings) {
    // Image::load() throws InputError naming the file when it is missing, a
    // folder or not an image, which is what a height map wants too; the depth
    // check only runs on a file that exists, so its failure cannot hide those.
    const bool sixteenBit = std::filesystem::is_regular_file(path) && isSixteenBit(path);
    if (sixteenBit) {
        throw InputError(path.string(), 0,
                         "a height map must have 8 bits per pixel; this image has 16. "
                         "Save it as an 8-bit grey image (PGM P5 with maxval 255, or an 8-bit grey PNG)");
    }
    Image image = Image::load(path);
    if (image.channels() != 1) {
        warnings << "stoa: warning: " << path.string() << ": a height map should be 8-bit grey; this image is "
                 << describeChannels(image.channels()) << ", so its luminance is used as the height\n";
        image = image.converted(1);
    }
    return image;
}

Image loadHeightMap(const std::filesystem::path& path) { return loadHeightMap(path, std::cerr); }

} // namespace stoa
