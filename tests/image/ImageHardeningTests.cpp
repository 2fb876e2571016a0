// Issue 14: the image and height-map loaders never hang, never accept
// garbage and say exactly what is wrong. Each case of the "Why" list,
// on a file generated here (the same inputs are in the fuzzers' regression
// corpus, tests/fuzz/make-regression-corpus.py).

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include <stb_image_write.h>
#include <sys/stat.h>

using stoa::Image;
using stoa::InputError;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Image::load(path) and loadHeightMap(path) must both throw an InputError
/// naming `path`, quickly; returns the message of Image::load's.
std::string refused(const fs::path& path) {
    const auto start = std::chrono::steady_clock::now();
    std::string message;
    try {
        (void)Image::load(path);
        FAIL("Image::load(" << path << ") did not throw");
    } catch (const InputError& error) {
        INFO(error.what());
        CHECK(error.file() == path.string());
        CHECK(error.line() == 0);
        message = error.message();
    }
    try {
        std::ostringstream warnings;
        (void)stoa::loadHeightMap(path, warnings);
        FAIL("loadHeightMap(" << path << ") did not throw");
    } catch (const InputError& error) {
        CHECK(error.file() == path.string());
    }
    // No decoding of a size the file cannot hold (that cost 13 s and 2.35 GB for one JPG).
    CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5.0);
    return message;
}

std::string littleEndian(std::uint32_t value, int bytes) {
    std::string out;
    for (int i = 0; i < bytes; ++i) out += static_cast<char>((value >> (8 * i)) & 0xff);
    return out;
}

/// A 54-byte BMP header (40-byte info header, 24 bits) and `pixels` after it.
std::string bmpHeader(std::int32_t width, std::int32_t height, const std::string& pixels = "") {
    return "BM" + littleEndian(54 + pixels.size(), 4) + littleEndian(0, 4) + littleEndian(54, 4) + littleEndian(40, 4) +
           littleEndian(std::uint32_t(width), 4) + littleEndian(std::uint32_t(height), 4) + littleEndian(1, 2) +
           littleEndian(24, 2) + std::string(24, '\0') + pixels;
}

/// A JPG written by stb_image_write, and the offset of its frame header (SOF0).
std::string jpg(const TempFolder& folder, int width, int height, std::size_t* frame) {
    std::string pixels;
    for (int i = 0; i < width * height * 3; ++i) pixels += static_cast<char>((i * 37 + i / 7) & 255);  // busy, not flat
    const fs::path path = folder / "source.jpg";
    REQUIRE(stbi_write_jpg(path.c_str(), width, height, 3, pixels.data(), 90) != 0);
    std::string bytes = readBytes(path);
    *frame = bytes.find("\xff\xc0");
    REQUIRE(*frame != std::string::npos);
    return bytes;
}

std::string withJpgSize(std::string bytes, std::size_t frame, int width, int height) {
    bytes[frame + 5] = static_cast<char>(height >> 8);
    bytes[frame + 6] = static_cast<char>(height & 255);
    bytes[frame + 7] = static_cast<char>(width >> 8);
    bytes[frame + 8] = static_cast<char>(width & 255);
    return bytes;
}

} // namespace

TEST_CASE("Issue 14: JPGs whose data cannot fill their header's size are refused", "[image][issue14]") {
    TempFolder folder("image-hardening");
    std::size_t frame = 0;
    const std::string good = jpg(folder, 64, 48, &frame);
    REQUIRE(Image::load(folder.write("good.jpg", good)).width() == 64);

    SECTION("SOF0 patched to 20000x20000") {
        const std::string message = refused(folder.write("huge.jpg", withJpgSize(good, frame, 20000, 20000)));
        CHECK(contains(message, "20000x20000"));
        CHECK(contains(message, "limit of 16384 pixels per side"));
    }
    SECTION("SOF0 patched upward a little: no garbage pixels") {
        const std::string message = refused(folder.write("taller.jpg", withJpgSize(good, frame, 64, 96)));
        CHECK(contains(message, "image data ends after"));
        CHECK(contains(message, "64x96"));
    }
    SECTION("a scan naming one component three times (found by fuzzing: UB inside stb_image)") {
        std::string bytes = good;
        const std::size_t scan = bytes.find("\xff\xda");
        REQUIRE(scan != std::string::npos);
        for (int i = 0; i < 3; ++i) bytes[scan + 5 + 2 * std::size_t(i)] = 1;
        CHECK(contains(refused(folder.write("repeated.jpg", bytes)), "names component 1 twice"));
    }
    SECTION("truncated: the message is about the JPG, not a PNG signature") {
        const std::string message = refused(folder.write("cut.jpg", good.substr(0, good.size() / 2)));
        CHECK(contains(message, "JPG"));
        CHECK_FALSE(contains(message, "png"));
    }
}

TEST_CASE("Issue 14: BMP and TGA headers are checked before anything is allocated", "[image][issue14]") {
    TempFolder folder("image-hardening");
    SECTION("a 54-byte BMP claiming 20000x20000") {
        CHECK(contains(refused(folder.write("huge.bmp", bmpHeader(20000, 20000))), "limit of 16384 pixels per side"));
    }
    SECTION("a 54-byte BMP claiming 4000x4000, within the limits but not in the file") {
        const std::string message = refused(folder.write("big.bmp", bmpHeader(4000, 4000)));
        CHECK(contains(message, "truncated"));
        CHECK(contains(message, "4000x4000"));
    }
    SECTION("a BMP of height -2147483648 (stb_image would negate INT_MIN)") {
        CHECK(contains(refused(folder.write("intmin.bmp", bmpHeader(2, INT32_MIN))), "2147483648"));
    }
    SECTION("an 18-byte TGA header claiming 4000x4000, within the limits but not in the file") {
        std::string tga(18, '\0');
        tga[2] = 2;  // uncompressed true colour
        tga.replace(12, 4, littleEndian(4000, 2) + littleEndian(4000, 2));
        tga[16] = 24;
        CHECK(contains(refused(folder.write("big.tga", tga)), "truncated"));
    }
}

TEST_CASE("Issue 14: image loaders refuse FIFOs and devices without blocking", "[image][issue14]") {
    TempFolder folder("image-hardening");
    for (const char* name : {"pipe.png", "pipe.pgm"}) {
        const fs::path fifo = folder / name;
        REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
        CHECK(contains(refused(fifo), "FIFO"));
    }
    if (fs::exists("/dev/zero")) CHECK(contains(refused("/dev/zero"), "character device"));
}

TEST_CASE("Issue 14: PGM headers are validated", "[image][issue14]") {
    TempFolder folder("image-hardening");
    CHECK(contains(refused(folder.write("negative.pgm", "P5\n-4 4\n255\n" + std::string(16, 'x'))), "negative width"));
    CHECK(contains(refused(folder.write("zero.pgm", "P5\n0 0\n255\n")), "at least 1"));
    CHECK(contains(refused(folder.write("wrap.pgm", "P5\n4294967297 1\n255\nx")), "4294967297"));
    CHECK(contains(refused(folder.write("maxval0.pgm", "P5\n2 2\n0\nxxxx")), "maxval 0"));
    CHECK(contains(refused(folder.write("maxval-big.pgm", "P5 2 2 99999999999999999999\nxxxx")), "far too large"));
    CHECK(contains(refused(folder.write("width-big.pgm", "P5 99999999999999999999 2 255\nxxxx")), "far too large"));
    CHECK(contains(refused(folder.write("short.pgm", "P5 4 4 255\n" + std::string(10, 'x'))), "truncated"));
}

TEST_CASE("Issue 14: OS/2 BMPs and ASCII PGM/PPM load", "[image][issue14]") {
    TempFolder folder("image-hardening");
    SECTION("an OS/2 BMP (12-byte info header) with varied pixels") {
        const int width = 7, height = 5, row = (width * 3 + 3) / 4 * 4;
        std::string pixels;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < row; ++x) pixels += static_cast<char>((x * 29 + y * 53 + 7) & 255);
        const std::string bmp = "BM" + littleEndian(26 + pixels.size(), 4) + littleEndian(0, 4) + littleEndian(26, 4) +
                                littleEndian(12, 4) + littleEndian(width, 2) + littleEndian(height, 2) +
                                littleEndian(1, 2) + littleEndian(24, 2) + pixels;
        const Image image = Image::load(folder.write("os2.bmp", bmp));
        REQUIRE(image.width() == width);
        REQUIRE(image.height() == height);
        // Rows are stored bottom-up as B, G, R.
        const auto stored = [&](int x, int y, int c) { return std::uint8_t(pixels[std::size_t((height - 1 - y) * row + x * 3 + c)]); };
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const glm::u8vec4 got = image.pixel(x, y);
                CHECK((got.r == stored(x, y, 2) && got.g == stored(x, y, 1) && got.b == stored(x, y, 0)));
            }
    }
    SECTION("ASCII P2, scaled from its maxval, as an image and as a height map") {
        const fs::path path = folder.write("ascii.pgm", "P2\n# comment\n3 2\n15\n0 5 10\n15 3 1\n");
        const Image image = Image::load(path);
        REQUIRE(image.channels() == 1);
        CHECK(int(image.pixel(0, 0).r) == 0);
        CHECK(int(image.pixel(1, 0).r) == 85);
        CHECK(int(image.pixel(0, 1).r) == 255);
        std::ostringstream warnings;
        const Image height = stoa::loadHeightMap(path, warnings);
        CHECK(height.width() == 3);
        CHECK(warnings.str().empty());
    }
    SECTION("ASCII P3") {
        const Image image = Image::load(folder.write("ascii.ppm", "P3 2 1 255\n255 0 0  0 255 0\n"));
        REQUIRE(image.channels() == 3);
        CHECK(image.pixel(0, 0) == glm::u8vec4(255, 0, 0, 255));
        CHECK(image.pixel(1, 0) == glm::u8vec4(0, 255, 0, 255));
    }
}

TEST_CASE("Issue 14: image messages name the real cause", "[image][issue14]") {
    TempFolder folder("image-hardening");
    SECTION("a truncated PNG") {
        const fs::path path = folder / "cut.png";
        Image(64, 64, 4).savePng(path);
        const std::string bytes = readBytes(path);
        CHECK(contains(refused(folder.write("cut80.png", bytes.substr(0, 80))), "truncated"));
        CHECK(contains(refused(folder.write("cut-end.png", bytes.substr(0, bytes.size() - 5))), "truncated"));
    }
    SECTION("a GIF named .png") {
        const std::string gif("GIF89a\x01\x00\x01\x00\x80\x00\x00\x00\x00\x00\xff\xff\xff!\xf9\x04\x01\x00\x00\x00\x00,"
                              "\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02" "D\x01\x00;", 43);
        CHECK(contains(refused(folder.write("really.png", gif)), "is a GIF, whatever its name says"));
    }
    SECTION("height maps: a symbolic link loop and a name too long are InputErrors") {
        const fs::path loop = folder / "loop.pgm";
        fs::create_symlink(loop, loop);
        CHECK(contains(refused(loop), "loop of symbolic links"));
        const fs::path longName = folder / (std::string(256, 'h') + ".pgm");
        CHECK(contains(refused(longName), "too long"));
    }
}

namespace {

// A PNG signature and its IHDR chunk only: enough for the header checks, which come first.
std::string pngHeader(std::uint32_t width, std::uint32_t height, int depth, int colourType) {
    const auto big = [](std::uint32_t value) {
        std::string bytes(4, '\0');
        for (int i = 0; i < 4; ++i) bytes[std::size_t(i)] = char((value >> (24 - 8 * i)) & 0xff);
        return bytes;
    };
    return std::string("\x89PNG\r\n\x1a\n", 8) + big(13) + "IHDR" + big(width) + big(height) + char(depth) +
           char(colourType) + std::string(3, '\0') + big(0) + big(0) + "IEND" + big(0);
}

} // namespace

TEST_CASE("Issue 25: a decompression bomb is refused from its header, before a pixel is decoded", "[image][issue25]") {
    TempFolder folder("image-hardening");
    SECTION("16384x16384, the size of a 270 KB all-black PNG that took 3.5 s and 529 MB") {
        const std::string message = refused(folder.write("bomb.png", pngHeader(16384, 16384, 8, 6)));
        CHECK(contains(message, "16384x16384 (256.0 megapixels)"));
        CHECK(contains(message, "past the limit of 16 megapixels (4096 x 4096)"));
    }
    SECTION("a 16-bit image counts twice") {
        CHECK(contains(refused(folder.write("deep.png", pngHeader(4096, 4096, 16, 0))), "at 16 bits a sample, which count twice"));
        std::string pgm = "P5\n4096 4096\n65535\n";
        CHECK(contains(refused(folder.write("deep.pgm", pgm)), "count twice"));
    }
    SECTION("4096x4096 at 8 bits, the limit itself, loads") {
        Image(4096, 4096, 1).savePng(folder / "limit.png");
        const Image image = Image::load(folder / "limit.png");
        CHECK(image.width() == 4096);
        CHECK(image.height() == 4096);
    }
}
