#include "FuzzTargets.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <sstream>

namespace stoa::fuzz {

bool obj(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find(mtlSeparator);
    const std::string objText = input.substr(0, split);
    const std::string mtlText = split == std::string::npos ? std::string() : input.substr(split + mtlSeparator.size());
    const MtlReader readMtl = [&](const std::filesystem::path&) { return mtlText; };
    std::ostringstream warnings;
    try {
        const Model model = parseObj(objText, "/nonexistent-fuzz-folder/model.obj", readMtl, warnings);
        (void)model;
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

bool image(const std::uint8_t* data, std::size_t size) {
    try {
        const Image decoded = Image::decode(data, size, "fuzz-image");
        // Each decoded image keeps its promise: the size its header gave, all its bytes.
        if (decoded.sizeInBytes() != static_cast<std::size_t>(decoded.width()) * decoded.height() * decoded.channels())
            __builtin_trap();
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

bool heightMap(const std::uint8_t* data, std::size_t size) {
    std::ostringstream warnings;
    try {
        const Image height = decodeHeightMap(data, size, "fuzz-height-map", warnings);
        if (height.channels() != 1) __builtin_trap();
        return true;
    } catch (const InputError& error) {
        (void)std::string(error.what());
        return false;
    }
}

} // namespace stoa::fuzz
