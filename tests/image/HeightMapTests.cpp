// loadHeightMap(): 8-bit grey passes through, colour falls back to luminance
// with a warning naming the file, 16-bit and undecodable files are InputErrors
// naming the file.

#include "catch.hpp"

#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <fstream>
#include <optional>
#include <sstream>
#include <string>

using stoa::Image;
using stoa::InputError;
using stoa::loadHeightMap;
using stoa::test::TempFolder;

namespace {

template <typename Function>
std::optional<InputError> inputErrorFrom(Function&& function) {
    try {
        function();
    } catch (const InputError& error) {
        return error;
    }
    return std::nullopt;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A binary PGM (P5): maxval 255 writes one byte per pixel, maxval > 255 two (big-endian).
std::filesystem::path writePgm(const TempFolder& folder, const std::string& name, int width, int height, int maxval,
                               const std::string& pixels) {
    std::ostringstream text;
    text << "P5\n" << width << ' ' << height << '\n' << maxval << '\n' << pixels;
    return folder.write(name, text.str());
}

} // namespace

TEST_CASE("an 8-bit grey PGM loads as it is, without a warning") {
    TempFolder folder("heightmap");
    const auto path = writePgm(folder, "ramp.pgm", 3, 2, 255, std::string("\x00\x10\x20\x40\x80\xff", 6));
    std::ostringstream warnings;
    const Image height = loadHeightMap(path, warnings);
    CHECK(warnings.str().empty());
    REQUIRE(height.channels() == 1);
    REQUIRE(height.width() == 3);
    REQUIRE(height.height() == 2);
    CHECK(height.pixel(0, 0).r == 0x00);   // row 0 is the file's first row
    CHECK(height.pixel(2, 0).r == 0x20);
    CHECK(height.pixel(0, 1).r == 0x40);
    CHECK(height.pixel(2, 1).r == 0xff);
}

TEST_CASE("a colour height map falls back to its luminance and warns, naming the file") {
    TempFolder folder("heightmap");
    Image colour(2, 1, 3);
    colour.setPixel(0, 0, {255, 0, 0, 255});
    colour.setPixel(1, 0, {40, 40, 40, 255});
    const auto path = folder / "colour.png";
    colour.savePng(path);

    std::ostringstream warnings;
    const Image height = loadHeightMap(path, warnings);
    REQUIRE(height.channels() == 1);
    // Rec. 709 luma of pure red is 0.2126 * 255 = 54.2; a grey keeps its value.
    CHECK(std::abs(static_cast<int>(height.pixel(0, 0).r) - 54) <= 1);
    CHECK(height.pixel(1, 0).r == 40);
    CHECK(contains(warnings.str(), path.string()));
    CHECK(contains(warnings.str(), "RGB"));
    CHECK(contains(warnings.str(), "luminance"));
}

TEST_CASE("grey + alpha and RGBA height maps also fall back with a warning") {
    TempFolder folder("heightmap");
    for (int channels : {2, 4}) {
        Image image(1, 1, channels);
        image.setPixel(0, 0, {90, 90, 90, 10});
        const auto path = folder / ("channels" + std::to_string(channels) + ".png");
        image.savePng(path);
        std::ostringstream warnings;
        const Image height = loadHeightMap(path, warnings);
        CHECK(height.channels() == 1);
        CHECK(height.pixel(0, 0).r == 90);  // alpha is ignored
        CHECK(contains(warnings.str(), path.string()));
    }
}

TEST_CASE("a 16-bit height map is an InputError naming the file") {
    TempFolder folder("heightmap");
    const auto path = writePgm(folder, "deep.pgm", 2, 1, 65535, std::string("\x12\x34\xff\xff", 4));
    std::ostringstream warnings;
    const auto error = inputErrorFrom([&] { (void)loadHeightMap(path, warnings); });
    REQUIRE(error);
    CHECK(error->file() == path.string());
    CHECK(error->line() == 0);
    CHECK(contains(error->message(), "16"));
    CHECK(contains(error->message(), "8-bit"));
}

TEST_CASE("a file that is not an image is an InputError naming the file") {
    TempFolder folder("heightmap");
    const auto path = folder.write("notes.pgm", "this is not a picture\n");
    const auto error = inputErrorFrom([&] { (void)loadHeightMap(path); });
    REQUIRE(error);
    CHECK(error->file() == path.string());
    CHECK(contains(std::string(error->what()), path.string()));
}

TEST_CASE("a missing height map or a folder is an InputError naming it") {
    TempFolder folder("heightmap");
    const auto missing = folder / "absent.pgm";
    auto error = inputErrorFrom([&] { (void)loadHeightMap(missing); });
    REQUIRE(error);
    CHECK(error->file() == missing.string());

    error = inputErrorFrom([&] { (void)loadHeightMap(folder.path()); });
    REQUIRE(error);
    CHECK(error->file() == folder.path().string());
    CHECK(contains(error->message(), "folder"));
}
