// Lab 10: the ground maps (stoa/crowd/GroundMaps.hpp) from files written
// here into a TempFolder, against the values the test put in them:
//   - loadGroundMaps with an 8-bit grey PNG (walkable where grey >= 128,
//     heights grey / 255), a 16-bit PGM (P5, maxval 65535) and a 16-bit grey
//     PNG (written by hand: stored deflate blocks, CRC-32 and Adler-32 here)
//     for heights (grey / 65535, so 1 and 256 are told from 0 and 1 / 255), a
//     colour collision map read as luminance (green walkable, red not: neither
//     the red channel nor the mean), the footprint and heightMin/Max copied,
//     no height map giving a 1 x 1 field of 0;
//   - a map under 2 x 2 texels refused naming the world file and the
//     <ground> line; a missing map refused naming its own file;
//   - flatGround: all walkable over the footprint, a 1 x 1 field of 0;
//   - terrainMesh: a vertex at each texel centre with its height, 6 indices
//     per quad of four neighbouring texels, every triangle counter-clockwise
//     seen from above (its normal's y > 0, whatever the heights), smooth
//     normals of unit length and straight up on flat ground; a 1 x 1 field gives
//     one quad over the footprint.
// writeExampleGroundMaps needs the stoa library: tests/labs/GroundTests.cpp.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/crowd/GroundMaps.hpp>
#include <stoa/image/Image.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace stoa;
using stoa::test::TempFolder;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string bigEndian32(std::uint32_t value) {
    return {static_cast<char>(value >> 24), static_cast<char>(value >> 16), static_cast<char>(value >> 8),
            static_cast<char>(value)};
}

std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (const char c : bytes) {
        crc ^= static_cast<std::uint8_t>(c);
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string pngChunk(const std::string& type, const std::string& data) {
    return bigEndian32(static_cast<std::uint32_t>(data.size())) + type + data + bigEndian32(crc32(type + data));
}

/// A 16-bit grey PNG, rows top first, its pixel data in one stored (uncompressed) deflate block.
std::string png16(int width, int height, const std::vector<std::uint16_t>& grey) {
    std::string raw;
    for (int row = 0; row < height; ++row) {
        raw += '\0';   // filter: none
        for (int col = 0; col < width; ++col) {
            const std::uint16_t v = grey[static_cast<std::size_t>(row * width + col)];
            raw += static_cast<char>(v >> 8);
            raw += static_cast<char>(v & 0xFF);
        }
    }
    REQUIRE(raw.size() < 65536);
    std::uint32_t a = 1, b = 0;   // Adler-32
    for (const char c : raw) {
        a = (a + static_cast<std::uint8_t>(c)) % 65521u;
        b = (b + a) % 65521u;
    }
    const auto length = static_cast<std::uint16_t>(raw.size());
    std::string zlib = "\x78\x01";
    zlib += '\x01';   // the final block, stored
    zlib += static_cast<char>(length & 0xFF);
    zlib += static_cast<char>(length >> 8);
    zlib += static_cast<char>(~length & 0xFF);
    zlib += static_cast<char>((~length >> 8) & 0xFF);
    zlib += raw + bigEndian32((b << 16) | a);
    const std::string header = bigEndian32(static_cast<std::uint32_t>(width)) +
                               bigEndian32(static_cast<std::uint32_t>(height)) + std::string("\x10\x00\x00\x00\x00", 5);
    return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", header) + pngChunk("IDAT", zlib) +
           pngChunk("IEND", "");
}

std::string pgm16(int width, int height, const std::vector<std::uint16_t>& grey) {
    std::string file = "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n65535\n";
    for (const std::uint16_t v : grey) {
        file += static_cast<char>(v >> 8);
        file += static_cast<char>(v & 0xFF);
    }
    return file;
}

/// An 8-bit grey image, rows top first.
Image greyImage(int width, int height, const std::vector<std::uint8_t>& grey) {
    Image image(width, height, 1);
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            const std::uint8_t g = grey[static_cast<std::size_t>(row * width + col)];
            image.setPixel(col, row, {g, g, g, 255});
        }
    return image;
}

GroundDescription description(const std::filesystem::path& collision, const std::filesystem::path& height) {
    GroundDescription ground;
    ground.collisionMap = collision;
    ground.heightMap = height;
    ground.footprintMin = {-6.0f, 2.0f};
    ground.footprintMax = {9.0f, 8.0f};
    ground.heightMin = -1.5f;
    ground.heightMax = 4.5f;
    ground.line = 17;
    return ground;
}

const std::vector<std::uint16_t> kSixteen{0, 1, 256, 32768, 65534, 65535};   // 3 x 2

void checkSixteenBitValues(const HeightField& heights) {
    REQUIRE(heights.grid.width == 3);
    REQUIRE(heights.grid.height == 2);
    REQUIRE(heights.values.size() == 6);
    for (std::size_t i = 0; i < 6; ++i) {
        INFO("texel " << i << " of grey " << kSixteen[i]);
        CHECK(std::abs(heights.values[i] - kSixteen[i] / 65535.0) < 1e-7);
    }
}

void expectMapError(const GroundDescription& ground, const std::filesystem::path& worldFile,
                    const std::string& file, int line, const std::string& part) {
    try {
        (void)loadGroundMaps(ground, worldFile);
    } catch (const InputError& error) {
        INFO(error.what());
        CHECK(error.file() == file);
        CHECK(error.line() == line);
        CHECK(contains(error.what(), part));
        return;
    }
    FAIL("loadGroundMaps did not throw; expected " << file << ":" << line);
}

} // namespace

TEST_CASE("Ground maps: an 8-bit grey PNG gives walkable texels and heights, row 0 first", "[crowd][ground]") {
    const TempFolder folder("ground-maps");
    const std::vector<std::uint8_t> grey{0, 127, 128, 255, 200, 10, 64, 191, 1, 254, 128, 127};   // 4 x 3
    greyImage(4, 3, grey).savePng(folder / "map.png");
    const GroundMaps maps = loadGroundMaps(description(folder / "map.png", folder / "map.png"), folder / "world.xml");
    REQUIRE(maps.collision.grid.width == 4);
    REQUIRE(maps.collision.grid.height == 3);
    CHECK(maps.collision.grid.footprintMin == glm::vec2(-6.0f, 2.0f));
    CHECK(maps.collision.grid.footprintMax == glm::vec2(9.0f, 8.0f));
    REQUIRE(maps.collision.walkable.size() == 12);
    REQUIRE(maps.heights.values.size() == 12);
    for (std::size_t i = 0; i < grey.size(); ++i) {
        INFO("texel " << i << " of grey " << int(grey[i]));
        CHECK(maps.collision.walkable[i] == (grey[i] >= 128 ? 1 : 0));
        CHECK(std::abs(maps.heights.values[i] - grey[i] / 255.0) < 1e-7);
    }
    CHECK(maps.heights.grid.width == 4);
    CHECK(maps.heights.grid.height == 3);
    CHECK(maps.heights.grid.footprintMin == glm::vec2(-6.0f, 2.0f));
    CHECK(maps.heights.heightMin == -1.5f);
    CHECK(maps.heights.heightMax == 4.5f);
}

// A regression test: stb_image 2.27 (Debian 12's) copies a 16-bit PNM's
// big-endian samples into memory as they are (on a little-endian machine grey
// 1 read as 256) and does not scale by maxval; GroundMaps.cpp reads PGMs itself.
TEST_CASE("Ground maps: a 16-bit PGM height map keeps its 16 bits", "[crowd][ground]") {
    const TempFolder folder("ground-maps");
    greyImage(2, 2, {255, 255, 255, 255}).savePng(folder / "white.png");
    folder.write("heights.pgm", pgm16(3, 2, kSixteen));
    const GroundMaps maps = loadGroundMaps(description(folder / "white.png", folder / "heights.pgm"), folder / "w.xml");
    checkSixteenBitValues(maps.heights);
    CHECK(maps.heights.grid.footprintMax == glm::vec2(9.0f, 8.0f));
}

TEST_CASE("Ground maps: a 16-bit PGM is scaled by its maxval, in binary and in text", "[crowd][ground]") {
    const TempFolder folder("ground-maps");
    greyImage(2, 2, {255, 255, 255, 255}).savePng(folder / "white.png");
    // maxval 1000: samples 0, 250, 500, 1000 are heights 0, 1/4, 1/2 and 1.
    std::string binary = "P5\n# a comment\n2 2\n1000\n";
    for (const int v : {0, 250, 500, 1000}) {
        binary += static_cast<char>(v >> 8);
        binary += static_cast<char>(v & 0xFF);
    }
    folder.write("binary.pgm", binary);
    folder.write("text.pgm", "P2\n2 2\n1000\n0 250\n500 1000\n");
    for (const char* name : {"binary.pgm", "text.pgm"}) {
        INFO(name);
        const GroundMaps maps = loadGroundMaps(description(folder / "white.png", folder / name), folder / "w.xml");
        CHECK(maps.heights.values == std::vector<float>{0.0f, 0.25f, 0.5f, 1.0f});
    }
    // A sample above maxval, and a file shorter than its header says.
    std::string above = "P5\n1 1\n1000\n";
    above += static_cast<char>(0x07);
    above += static_cast<char>(0xD0);   // 2000
    folder.write("above.pgm", above);
    folder.write("short.pgm", "P5\n2 2\n1000\n\x01");
    for (const char* name : {"above.pgm", "short.pgm"}) {
        INFO(name);
        CHECK_THROWS_AS(loadGroundMaps(description(folder / "white.png", folder / name), folder / "w.xml"), InputError);
    }
}

TEST_CASE("Ground maps: a 16-bit grey PNG height map keeps its 16 bits", "[crowd][ground]") {
    const TempFolder folder("ground-maps");
    greyImage(2, 2, {255, 255, 255, 255}).savePng(folder / "white.png");
    folder.write("heights.png", png16(3, 2, kSixteen));
    // The hand-made file is a valid PNG: Image reads it, to 8 bits.
    const Image eight = Image::load(folder / "heights.png", 1);
    CHECK(eight.width() == 3);
    CHECK(eight.pixel(2, 1).r == 255);
    const GroundMaps maps = loadGroundMaps(description(folder / "white.png", folder / "heights.png"), folder / "w.xml");
    checkSixteenBitValues(maps.heights);
}

TEST_CASE("Ground maps: a colour collision map is read as luminance", "[crowd][ground]") {
    const TempFolder folder("ground-maps");
    Image colour(4, 2, 3);
    // Row 0: red, green, blue, yellow; row 1: white, black, grey 120, grey 140.
    const glm::u8vec4 pixels[] = {{255, 0, 0, 255},     {0, 255, 0, 255}, {0, 0, 255, 255},     {255, 255, 0, 255},
                                  {255, 255, 255, 255}, {0, 0, 0, 255},   {120, 120, 120, 255}, {140, 140, 140, 255}};
    for (int i = 0; i < 8; ++i) colour.setPixel(i % 4, i / 4, pixels[i]);
    colour.savePng(folder / "colour.png");
    const GroundMaps maps = loadGroundMaps(description(folder / "colour.png", ""), folder / "w.xml");
    // Luminance (about 0.3 R + 0.59 G + 0.11 B): red 76, green 150, blue 29, yellow 226.
    CHECK(maps.collision.walkable == std::vector<std::uint8_t>{0, 1, 0, 1, 1, 0, 0, 1});
}

TEST_CASE("Ground maps: a world without a height map stands flat at heightMin", "[crowd][ground]") {
    const TempFolder folder("ground-maps");
    greyImage(3, 2, {255, 0, 255, 0, 255, 0}).savePng(folder / "c.png");
    const GroundMaps maps = loadGroundMaps(description(folder / "c.png", ""), folder / "w.xml");
    CHECK(maps.heights.grid.width == 1);
    CHECK(maps.heights.grid.height == 1);
    CHECK(maps.heights.values == std::vector<float>{0.0f});
    CHECK(maps.heights.heightMin == -1.5f);
    CHECK(maps.heights.grid.footprintMin == glm::vec2(-6.0f, 2.0f));
    CHECK(maps.heights.grid.footprintMax == glm::vec2(9.0f, 8.0f));
}

TEST_CASE("Ground maps: a map under 2 x 2 texels is refused naming the world file and the <ground> line",
          "[crowd][ground]") {
    const TempFolder folder("ground-maps");
    greyImage(1, 1, {255}).savePng(folder / "one.png");
    greyImage(5, 1, {255, 255, 255, 255, 255}).savePng(folder / "row.png");
    greyImage(2, 2, {255, 255, 255, 255}).savePng(folder / "two.png");
    const std::string world = (folder / "world.xml").string();
    expectMapError(description(folder / "one.png", ""), folder / "world.xml", world, 17, "one.png");
    expectMapError(description(folder / "row.png", ""), folder / "world.xml", world, 17, "5 x 1");
    expectMapError(description(folder / "two.png", folder / "one.png"), folder / "world.xml", world, 17, "one.png");
    CHECK_NOTHROW(loadGroundMaps(description(folder / "two.png", folder / "two.png"), folder / "world.xml"));
}

TEST_CASE("Ground maps: a map that does not load is refused at the world's <ground> line, naming the map",
          "[crowd][ground][issue25]") {
    const TempFolder folder("ground-maps");
    greyImage(2, 2, {255, 255, 255, 255}).savePng(folder / "two.png");
    const std::string world = (folder / "world.xml").string(), missing = (folder / "missing.png").string();
    expectMapError(description(folder / "missing.png", ""), folder / "world.xml", world, 17,
                   "<ground> collision map: " + missing);
    expectMapError(description(folder / "two.png", folder / "missing.png"), folder / "world.xml", world, 17,
                   "<ground> height map: " + missing);
}

TEST_CASE("Ground maps: flatGround is walkable everywhere at height 0", "[crowd][ground]") {
    const GroundMaps maps = flatGround({-3.0f, -1.0f}, {5.0f, 7.0f}, 8);
    CHECK(maps.collision.grid.width == 8);
    CHECK(maps.collision.grid.height == 8);
    CHECK(maps.collision.grid.footprintMin == glm::vec2(-3.0f, -1.0f));
    CHECK(maps.collision.grid.footprintMax == glm::vec2(5.0f, 7.0f));
    CHECK(maps.collision.walkable == std::vector<std::uint8_t>(64, 1));
    CHECK(maps.heights.grid.width == 1);
    CHECK(maps.heights.grid.height == 1);
    CHECK(maps.heights.values == std::vector<float>{0.0f});
    CHECK(maps.heights.heightMin == 0.0f);
    CHECK(maps.heights.heightMax == 0.0f);
    CHECK(flatGround({0.0f, 0.0f}, {1.0f, 1.0f}).collision.walkable.size() == 64u * 64u);
}

TEST_CASE("Ground maps: terrainMesh puts a vertex at each texel centre, triangles facing up", "[crowd][ground]") {
    HeightField field;
    field.grid = {5, 4, {-4.0f, 10.0f}, {6.0f, 18.0f}};   // texels of 2 m x 2 m
    for (int i = 0; i < 20; ++i) field.values.push_back(static_cast<float>((i * 7) % 11) / 10.0f);
    field.heightMin = -1.0f;
    field.heightMax = 3.0f;
    const Mesh mesh = terrainMesh(field);
    REQUIRE(mesh.vertices.size() == 20);
    CHECK(mesh.indices.size() == 6u * 4u * 3u);
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 5; ++col) {
            const float x = -4.0f + 2.0f * col + 1.0f, z = 10.0f + 2.0f * row + 1.0f;
            const float y = -1.0f + 4.0f * field.values[static_cast<std::size_t>(row * 5 + col)];
            int found = 0;
            for (const Vertex& vertex : mesh.vertices)
                found += glm::length(vertex.position - glm::vec3(x, y, z)) < 1e-5f;
            INFO("texel (" << col << ", " << row << ")");
            CHECK(found == 1);
        }
    }
    for (const Vertex& vertex : mesh.vertices) {
        CHECK(std::abs(glm::length(vertex.normal) - 1.0f) < 1e-5f);
        CHECK(vertex.normal.y > 0.0f);
    }
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        REQUIRE(mesh.indices[i] < 20);
        REQUIRE(mesh.indices[i + 1] < 20);
        REQUIRE(mesh.indices[i + 2] < 20);
        const glm::vec3 a = mesh.vertices[mesh.indices[i]].position;
        const glm::vec3 b = mesh.vertices[mesh.indices[i + 1]].position;
        const glm::vec3 c = mesh.vertices[mesh.indices[i + 2]].position;
        INFO("triangle " << i / 3);
        // y of the cross product is the signed area seen from above: the heights do not enter it.
        CHECK(glm::cross(b - a, c - a).y == Approx(4.0f));   // twice a half of a 2 m x 2 m cell
    }
}

TEST_CASE("Ground maps: terrainMesh of flat ground has its normals straight up", "[crowd][ground]") {
    HeightField field;
    field.grid = {6, 3, {0.0f, 0.0f}, {12.0f, 3.0f}};
    field.values.assign(18, 0.25f);
    field.heightMax = 8.0f;
    const Mesh mesh = terrainMesh(field);
    REQUIRE(mesh.vertices.size() == 18);
    for (const Vertex& vertex : mesh.vertices) {
        CHECK(vertex.position.y == Approx(2.0f));
        CHECK(glm::length(vertex.normal - glm::vec3(0.0f, 1.0f, 0.0f)) < 1e-6f);
    }
    // A 1 x 1 field (no height map): one quad over the footprint at heightMin, facing up.
    HeightField flat;
    flat.grid = {1, 1, {-2.0f, -3.0f}, {4.0f, 5.0f}};
    flat.values = {0.0f};
    flat.heightMin = 0.5f;
    const Mesh quad = terrainMesh(flat);
    REQUIRE(quad.vertices.size() == 4);
    REQUIRE(quad.indices.size() == 6);
    for (const Vertex& vertex : quad.vertices) {
        CHECK(vertex.position.y == 0.5f);
        CHECK((vertex.position.x == -2.0f || vertex.position.x == 4.0f));
        CHECK((vertex.position.z == -3.0f || vertex.position.z == 5.0f));
        CHECK(vertex.normal == glm::vec3(0.0f, 1.0f, 0.0f));
    }
    for (std::size_t i = 0; i < 6; i += 3) {
        const glm::vec3 a = quad.vertices[quad.indices[i]].position;
        CHECK(glm::cross(quad.vertices[quad.indices[i + 1]].position - a, quad.vertices[quad.indices[i + 2]].position - a).y > 0.0f);
    }
}
