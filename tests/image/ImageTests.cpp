// Image: construction, pixel access, conversion, flipping, and loading and
// saving through stb_image. Files are written into a temporary folder by the
// tests themselves (stb_image_write for BMP, TGA, JPG; PGM/PPM by hand).

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/image/Image.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>

#include <stb_image_write.h>

using stoa::Image;
using stoa::InputError;
using stoa::test::TempFolder;

namespace {

// A deterministic pattern with different values in every channel.
Image pattern(int width, int height, int channels) {
    Image image(width, height, channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                image.data()[(y * width + x) * channels + c] = static_cast<std::uint8_t>(x * 7 + y * 13 + c * 50);
    return image;
}

bool sameBytes(const Image& a, const Image& b) {
    return a.width() == b.width() && a.height() == b.height() && a.channels() == b.channels() &&
           std::equal(a.data(), a.data() + a.sizeInBytes(), b.data());
}

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

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

} // namespace

TEST_CASE("Image: a new image is black, with opaque alpha where it has alpha", "[image]") {
    for (int channels = 1; channels <= 4; ++channels) {
        const Image image(5, 3, channels);
        CHECK(image.width() == 5);
        CHECK(image.height() == 3);
        CHECK(image.channels() == channels);
        CHECK(image.sizeInBytes() == std::size_t(5 * 3 * channels));
        CHECK_FALSE(image.empty());
        const glm::u8vec4 corner = image.pixel(4, 2);
        CHECK(corner == glm::u8vec4(0, 0, 0, 255));
        const bool hasAlpha = channels == 2 || channels == 4;
        CHECK(int(image.data()[channels - 1]) == (hasAlpha ? 255 : 0));
    }
    CHECK(Image().empty());
}

TEST_CASE("Image: pixel() reads RGBA and setPixel() writes the channels the image has", "[image]") {
    Image grey(2, 2, 1);
    grey.setPixel(1, 0, {90, 10, 20, 30});
    CHECK(grey.pixel(1, 0) == glm::u8vec4(90, 90, 90, 255));
    CHECK(grey.data()[1] == 90);

    Image greyAlpha(2, 2, 2);
    greyAlpha.setPixel(0, 1, {40, 1, 2, 77});
    CHECK(greyAlpha.pixel(0, 1) == glm::u8vec4(40, 40, 40, 77));

    Image rgb(2, 2, 3);
    rgb.setPixel(1, 1, {1, 2, 3, 4});
    CHECK(rgb.pixel(1, 1) == glm::u8vec4(1, 2, 3, 255));
    CHECK(rgb.data()[9] == 1);  // (1, 1) starts at (1 * 2 + 1) * 3: rows are top-down, tightly packed

    Image rgba(2, 2, 4);
    rgba.setPixel(0, 1, {5, 6, 7, 8});
    CHECK(rgba.pixel(0, 1) == glm::u8vec4(5, 6, 7, 8));
    CHECK(rgba.pixel(0, 0) == glm::u8vec4(0, 0, 0, 255));
}

TEST_CASE("Image: converted() between channel counts", "[image]") {
    Image rgba(4, 1, 4);
    rgba.setPixel(0, 0, {255, 255, 255, 10});
    rgba.setPixel(1, 0, {255, 0, 0, 20});
    rgba.setPixel(2, 0, {0, 255, 0, 30});
    rgba.setPixel(3, 0, {0, 0, 255, 40});

    // Rec. 709 luma: 0.2126 R + 0.7152 G + 0.0722 B.
    const Image grey = rgba.converted(1);
    REQUIRE(grey.channels() == 1);
    CHECK(int(grey.data()[0]) == 255);
    CHECK(int(grey.data()[1]) == 54);
    CHECK(int(grey.data()[2]) == 182);
    CHECK(int(grey.data()[3]) == 18);

    const Image greyAlpha = rgba.converted(2);
    CHECK(greyAlpha.pixel(1, 0) == glm::u8vec4(54, 54, 54, 20));

    const Image rgb = rgba.converted(3);
    CHECK(rgb.pixel(3, 0) == glm::u8vec4(0, 0, 255, 255));
    CHECK(rgb.sizeInBytes() == 12);

    const Image back = grey.converted(4);
    CHECK(back.pixel(2, 0) == glm::u8vec4(182, 182, 182, 255));
    CHECK(greyAlpha.converted(4).pixel(3, 0) == glm::u8vec4(18, 18, 18, 40));
    CHECK(sameBytes(rgba.converted(4), rgba));
}

TEST_CASE("Image: flipVertically() swaps rows and undoes itself", "[image]") {
    for (int height : {1, 2, 3, 6}) {
        const Image original = pattern(3, height, 3);
        Image flipped = original;
        flipped.flipVertically();
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < 3; ++x) CHECK(flipped.pixel(x, y) == original.pixel(x, height - 1 - y));
        flipped.flipVertically();
        CHECK(sameBytes(flipped, original));
    }
}

TEST_CASE("Image: PNG round trip keeps every channel count", "[image]") {
    TempFolder folder("image-png");
    for (int channels = 1; channels <= 4; ++channels) {
        const Image original = pattern(17, 9, channels);  // odd width: rows are not 4-byte aligned
        const auto path = folder / ("pattern" + std::to_string(channels) + ".png");
        original.savePng(path);
        const Image loaded = Image::load(path);
        CHECK(sameBytes(loaded, original));
    }
}

TEST_CASE("Image: load() converts to the channel count asked for", "[image]") {
    TempFolder folder("image-convert");
    const Image rgb = pattern(6, 4, 3);
    const auto path = folder / "rgb.png";
    rgb.savePng(path);
    for (int channels = 1; channels <= 4; ++channels) {
        const Image loaded = Image::load(path, channels);
        REQUIRE(loaded.channels() == channels);
        CHECK(loaded.width() == 6);
        CHECK(loaded.height() == 4);
    }
    for (int channels = 1; channels <= 4; ++channels)
        CHECK(sameBytes(Image::load(path, channels), rgb.converted(channels)));  // the same grey weights too
}

TEST_CASE("Image: loads BMP, TGA, JPG and PGM/PPM files", "[image]") {
    TempFolder folder("image-formats");
    const std::string prefix = folder.path().string() + "/";

    SECTION("BMP, 24 and 32 bits") {
        for (int channels : {3, 4}) {
            const Image original = pattern(7, 5, channels);
            const std::string path = prefix + "pattern" + std::to_string(channels) + ".bmp";
            REQUIRE(stbi_write_bmp(path.c_str(), 7, 5, channels, original.data()) != 0);
            const Image loaded = Image::load(path, channels);
            REQUIRE(loaded.channels() == channels);
            for (int y = 0; y < 5; ++y)
                for (int x = 0; x < 7; ++x) {
                    const glm::u8vec4 got = loaded.pixel(x, y), want = original.pixel(x, y);
                    CHECK((got.r == want.r && got.g == want.g && got.b == want.b));
                }
        }
    }
    SECTION("TGA, grey, RGB and RGBA") {
        for (int channels : {1, 3, 4}) {
            const Image original = pattern(9, 4, channels);
            const std::string path = prefix + "pattern" + std::to_string(channels) + ".tga";
            REQUIRE(stbi_write_tga(path.c_str(), 9, 4, channels, original.data()) != 0);
            CHECK(sameBytes(Image::load(path), original));
        }
    }
    SECTION("JPG, lossy but close") {
        Image original(32, 32, 3);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) original.setPixel(x, y, {std::uint8_t(x * 8), std::uint8_t(y * 8), 128, 255});
        const std::string path = prefix + "gradient.jpg";
        REQUIRE(stbi_write_jpg(path.c_str(), 32, 32, 3, original.data(), 95) != 0);
        const Image loaded = Image::load(path);
        REQUIRE(loaded.channels() == 3);
        REQUIRE(loaded.width() == 32);
        int largest = 0;
        for (std::size_t i = 0; i < loaded.sizeInBytes(); ++i)
            largest = std::max(largest, std::abs(loaded.data()[i] - original.data()[i]));
        CHECK(largest <= 12);
    }
    SECTION("PGM (P5) and PPM (P6)") {
        const Image grey = pattern(4, 3, 1);
        writeBytes(prefix + "grey.pgm",
                   "P5\n# a comment\n4 3\n255\n" + std::string(grey.data(), grey.data() + grey.sizeInBytes()));
        CHECK(sameBytes(Image::load(prefix + "grey.pgm"), grey));

        const Image rgb = pattern(2, 5, 3);
        writeBytes(prefix + "rgb.ppm", "P6 2 5 255\n" + std::string(rgb.data(), rgb.data() + rgb.sizeInBytes()));
        CHECK(sameBytes(Image::load(prefix + "rgb.ppm"), rgb));
    }
}

TEST_CASE("Image: load() names the file and the reason on bad input", "[image]") {
    TempFolder folder("image-bad");

    SECTION("a missing file") {
        const auto path = folder / "missing.png";
        const auto error = inputErrorFrom([&] { Image::load(path); });
        REQUIRE(error);
        CHECK(error->file() == path.string());
        CHECK(error->line() == 0);
        CHECK(error->message() == "the file does not exist");
        CHECK(contains(error->what(), "missing.png"));
    }
    SECTION("a folder") {
        const auto error = inputErrorFrom([&] { Image::load(folder.path()); });
        REQUIRE(error);
        CHECK(contains(error->message(), "this is a folder, not an image file"));
    }
    SECTION("a file that is not an image") {
        const auto path = folder / "garbage.png";
        writeBytes(path, "this is text, not pixels\n");
        const auto error = inputErrorFrom([&] { Image::load(path); });
        REQUIRE(error);
        CHECK(error->file() == path.string());
        CHECK(contains(error->message(), "not a PNG, JPG, BMP, TGA or PGM/PPM image"));
        CHECK(contains(error->what(), "garbage.png"));
    }
    SECTION("an empty file") {
        const auto path = folder / "empty.jpg";
        writeBytes(path, "");
        const auto error = inputErrorFrom([&] { Image::load(path); });
        REQUIRE(error);
        CHECK(error->message() == "the file is empty");
    }
    SECTION("a truncated PNG") {
        const auto path = folder / "truncated.png";
        pattern(64, 64, 4).savePng(path);
        std::filesystem::resize_file(path, 80);
        CHECK(inputErrorFrom([&] { Image::load(path); }));
    }
    SECTION("a PNG that cannot be written") {
        const auto path = folder / "no-such-folder" / "out.png";
        const auto error = inputErrorFrom([&] { pattern(2, 2, 3).savePng(path); });
        REQUIRE(error);
        CHECK(error->file() == path.string());
        CHECK(error->message() == "cannot write the PNG: its folder " + (folder / "no-such-folder").string() + " does not exist");
        std::filesystem::create_directory(folder / "in-the-way.png");
        const auto blocked = inputErrorFrom([&] { pattern(2, 2, 3).savePng(folder / "in-the-way.png"); });
        REQUIRE(blocked);
        CHECK(blocked->message() == "cannot write the PNG: a folder of that name is in the way");
    }
}
