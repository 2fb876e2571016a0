// The texture maps a mesh can name: PNG, BMP, PGM, TGA and JPG at 8, 24 and
// 32 bits per pixel, decoded by Image::load and uploaded with mipmaps by
// Texture2D; broken files are InputErrors naming the file; TextureCache loads
// each file once; MeshObject binds the maps. Fixtures are written into a
// temporary folder (stb_image_write, and by hand for PGM and 8-bit BMP).

#include "GlTestSupport.hpp"
#include "TempFolder.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/ShaderSource.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/gl/VertexArray.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/scene/MeshObject.hpp>

#include <stb_image_write.h>

#include <cmath>
#include <functional>
#include <string>

using namespace stoa;
using stoa::test::describe;
using stoa::test::glShadersDir;
using stoa::test::TempFolder;

namespace {

/// Samples unit 0 at `uv` from mipmap level `lod` (textureLod: no derivatives involved).
glm::u8vec4 sampleLevel(const Texture2D& texture, glm::vec2 uv, float lod) {
    const char* fragment = "#version 330 core\n"
                           "uniform sampler2D uTexture;\n"
                           "uniform vec2 uUv;\n"
                           "uniform float uLod;\n"
                           "out vec4 fragColor;\n"
                           "void main() { fragColor = textureLod(uTexture, uUv, uLod); }\n";
    const Program program = Program::fromSources(ShaderSource::load(glShadersDir / "fullscreen.vert", {}),
                                                 ShaderSource::fromText(fragment, "level.frag", {}));
    VertexArray empty;
    Framebuffer target(2, 2);
    beginPass(passInto(target, RenderState::overlay()));
    texture.bind(0);
    program.use();
    program.set("uTexture", 0);
    program.set("uUv", uv);
    program.set("uLod", lod);
    empty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return target.readColor().pixel(1, 1);
}

/// An 8x8 checkerboard of 2x2 squares in `dark` and `light` (top-left square dark).
Image checkerboard(int channels, glm::u8vec4 dark, glm::u8vec4 light) {
    Image image(8, 8, channels);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) image.setPixel(x, y, ((x / 2 + y / 2) % 2 == 0) ? dark : light);
    return image;
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void putLittleEndian(std::string& bytes, std::uint32_t value, int size) {
    for (int i = 0; i < size; ++i) bytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

/// An 8-bit paletted BMP of `image` (grey, one channel): palette entry i is grey level i.
std::string paletteBmp(const Image& image) {
    const int rowBytes = (image.width() + 3) / 4 * 4;
    const std::uint32_t dataOffset = 14 + 40 + 256 * 4;
    std::string bytes = "BM";
    putLittleEndian(bytes, dataOffset + rowBytes * image.height(), 4);
    putLittleEndian(bytes, 0, 4);
    putLittleEndian(bytes, dataOffset, 4);
    putLittleEndian(bytes, 40, 4);  // BITMAPINFOHEADER
    putLittleEndian(bytes, image.width(), 4);
    putLittleEndian(bytes, image.height(), 4);  // positive: rows bottom-up
    putLittleEndian(bytes, 1, 2);
    putLittleEndian(bytes, 8, 2);  // bits per pixel
    putLittleEndian(bytes, 0, 4);  // no compression
    putLittleEndian(bytes, rowBytes * image.height(), 4);
    putLittleEndian(bytes, 2835, 4);
    putLittleEndian(bytes, 2835, 4);
    putLittleEndian(bytes, 256, 4);
    putLittleEndian(bytes, 0, 4);
    for (int i = 0; i < 256; ++i) putLittleEndian(bytes, 0x00010101u * i, 4);  // B G R 0
    for (int y = image.height() - 1; y >= 0; --y) {
        for (int x = 0; x < image.width(); ++x) bytes.push_back(static_cast<char>(image.pixel(x, y).r));
        bytes.append(rowBytes - image.width(), '\0');
    }
    return bytes;
}

struct Fixture {
    std::string name;    // file name; its extension picks the format
    int bitsPerPixel;    // as stored in the file
    int channels;        // what Image::load returns
    bool lossy;          // JPG
    std::function<void(const std::string& path, const Image& image)> write;
};

/// One fixture per format and depth the framework promises to read. (No 8-bit
/// JPG: stb_image_write stores grey as three channels; JPG has no alpha.)
std::vector<Fixture> fixtures() {
    auto png = [](const std::string& path, const Image& image) {
        REQUIRE(stbi_write_png(path.c_str(), image.width(), image.height(), image.channels(), image.data(), 0) != 0);
    };
    auto tga = [](const std::string& path, const Image& image) {
        stbi_write_tga_with_rle = 0;
        REQUIRE(stbi_write_tga(path.c_str(), image.width(), image.height(), image.channels(), image.data()) != 0);
    };
    auto bmp = [](const std::string& path, const Image& image) {
        REQUIRE(stbi_write_bmp(path.c_str(), image.width(), image.height(), image.channels(), image.data()) != 0);
    };
    auto jpg = [](const std::string& path, const Image& image) {
        REQUIRE(stbi_write_jpg(path.c_str(), image.width(), image.height(), image.channels(), image.data(), 100) != 0);
    };
    auto pgm = [](const std::string& path, const Image& image) {
        writeBytes(path, "P5\n" + std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n255\n" +
                             std::string(image.data(), image.data() + image.sizeInBytes()));
    };
    auto bmp8 = [](const std::string& path, const Image& image) { writeBytes(path, paletteBmp(image)); };
    return {
        {"grey.png", 8, 1, false, png},   {"rgb.png", 24, 3, false, png},  {"rgba.png", 32, 4, false, png},
        {"grey.tga", 8, 1, false, tga},   {"rgb.tga", 24, 3, false, tga},  {"rgba.tga", 32, 4, false, tga},
        {"grey.bmp", 8, 3, false, bmp8},  {"rgb.bmp", 24, 3, false, bmp},  {"rgba.bmp", 32, 4, false, bmp},
        {"rgb.jpg", 24, 3, true, jpg},    {"grey.pgm", 8, 1, false, pgm},
    };
}

} // namespace

TEST_CASE("Texture formats: PNG, BMP, PGM, TGA and JPG at 8, 24 and 32 bits load and mipmap") {
    HeadlessContext context;
    TempFolder folder("texture-formats");
    const glm::u8vec4 dark(40, 60, 80, 255), light(200, 180, 160, 255);
    for (const Fixture& fixture : fixtures()) {
        INFO(fixture.name << " (" << fixture.bitsPerPixel << " bits)");
        const int fileChannels = fixture.bitsPerPixel / 8;
        // An 8-bit file holds grey: both squares use their r for every channel.
        const glm::u8vec4 darkInFile = fileChannels == 1 ? glm::u8vec4(dark.r, dark.r, dark.r, 255) : dark;
        const glm::u8vec4 lightInFile = fileChannels == 1 ? glm::u8vec4(light.r, light.r, light.r, 255) : light;
        const Image original = checkerboard(fileChannels, darkInFile, lightInFile);
        const std::string path = (folder / fixture.name).string();
        fixture.write(path, original);

        const Image loaded = Image::load(path);
        CHECK(loaded.channels() == fixture.channels);
        CHECK(loaded.width() == 8);
        CHECK(loaded.height() == 8);

        const Texture2D texture = Texture2D::fromFile(path);  // mipmaps by default
        texture.bind(0);
        GLint levelWidth = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH, &levelWidth);
        CHECK(levelWidth == 1);  // the chain 8, 4, 2, 1

        const int tolerance = fixture.lossy ? 12 : 2;
        // Level 0 near uv (0, 0) is the image's bottom-left pixel, row 7 of the file.
        const glm::u8vec4 corner = sampleLevel(texture, {0.0625f, 0.0625f}, 0.0f);
        const glm::u8vec4 bottomLeft = original.pixel(0, 7);
        const glm::u8vec4 bottomLeftRgba = fileChannels == 1 ? glm::u8vec4(bottomLeft.r, bottomLeft.r, bottomLeft.r, 255)
                                                             : bottomLeft;
        INFO("level 0 at the bottom-left corner: " << describe(corner) << ", expected " << describe(bottomLeftRgba));
        CHECK(test::near(corner, bottomLeftRgba, tolerance));
        // Level 3 is one texel, the mean of the checkerboard: half dark, half light.
        const glm::u8vec4 mean = sampleLevel(texture, {0.5f, 0.5f}, 3.0f);
        const glm::u8vec4 expected((glm::ivec4(darkInFile) + glm::ivec4(lightInFile) + 1) / 2);
        INFO("level 3: " << describe(mean) << ", expected about " << describe(expected));
        CHECK(test::near(mean, expected, tolerance + 2));
    }
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Texture formats: a truncated or corrupt file is an InputError naming it") {
    HeadlessContext context;
    TempFolder folder("texture-broken");
    const glm::u8vec4 dark(40, 60, 80, 255), light(200, 180, 160, 255);
    for (const Fixture& fixture : fixtures()) {
        const Image original = checkerboard(fixture.bitsPerPixel / 8, dark, light);
        for (const char* damage : {"truncated", "corrupt"}) {
            const std::string path = (folder / (std::string(damage) + "_" + fixture.name)).string();
            fixture.write(path, original);
            const auto size = std::filesystem::file_size(path);
            if (std::string(damage) == "truncated") {
                std::filesystem::resize_file(path, size / 2);
            } else {
                // The header's first bytes (the signature or the size fields) overwritten.
                std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
                file.write("\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f\x7f", 18);
            }
            INFO(damage << " " << fixture.name);
            try {
                (void)Texture2D::fromFile(path);
                FAIL("Texture2D::fromFile() did not throw for " << path);
            } catch (const InputError& error) {
                CHECK(error.file() == path);
                CHECK(std::string(error.what()).find(std::string(damage) + "_" + fixture.name) != std::string::npos);
            }
        }
    }
}

TEST_CASE("TextureCache: each file is loaded once while someone holds it") {
    HeadlessContext context;
    TempFolder folder("texture-cache");
    checkerboard(3, {0, 0, 0, 255}, {255, 255, 255, 255}).savePng(folder / "board.png");
    TextureCache cache;
    {
        const auto first = cache.load(folder / "board.png");
        const auto second = cache.load(folder.path() / "." / "board.png");  // the same file, spelled otherwise
        CHECK(first == second);
        CHECK(cache.loadCount() == 1);
        CHECK(cache.aliveCount() == 1);
        CHECK(first->width() == 8);
    }
    CHECK(cache.aliveCount() == 0);  // the cache holds no texture itself
    const auto again = cache.load(folder / "board.png");
    CHECK(cache.loadCount() == 2);

    try {
        (void)cache.load(folder / "missing.png");
        FAIL("a missing file should throw");
    } catch (const InputError& error) {
        CHECK(error.file().find("missing.png") != std::string::npos);
    }
    CHECK(cache.loadCount() == 2);
}

// MeshObject::draw() sets uModel from the model matrix (a test double here).
TEST_CASE("MeshObject binds the material's diffuse and specular maps") {
    HeadlessContext context;
    TempFolder folder("mesh-maps");
    Image red(4, 4, 3), grey(4, 4, 1);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            red.setPixel(x, y, {255, 0, 0, 255});
            grey.setPixel(x, y, {128, 128, 128, 255});
        }
    red.savePng(folder / "red.png");
    grey.savePng(folder / "grey.png");

    // Draws a full-screen quad (a plane seen from above is not needed: the
    // vertex stage ignores the matrices) and shows the map flags and samples.
    const char* vertex = "#version 330 core\n"
                         "layout(location = 0) in vec3 aPosition;\n"
                         "layout(location = 2) in vec2 aUv;\n"
                         "out vec2 vUv;\n"
                         "void main() { vUv = aUv; gl_Position = vec4(aPosition.xz * 4.0, 0.0, 1.0); }\n";
    const char* fragment = "#version 330 core\n"
                           "in vec2 vUv;\n"
                           "uniform sampler2D uDiffuseMap;\n"
                           "uniform bool uHasDiffuseMap;\n"
                           "uniform sampler2D uSpecularMap;\n"
                           "uniform bool uHasSpecularMap;\n"
                           "out vec4 fragColor;\n"
                           "void main() {\n"
                           "    vec3 diffuse = uHasDiffuseMap ? texture(uDiffuseMap, vUv).rgb : vec3(0.0, 0.0, 1.0);\n"
                           "    float specular = uHasSpecularMap ? texture(uSpecularMap, vUv).r : 1.0;\n"
                           "    fragColor = vec4(diffuse, specular);\n"
                           "}\n";
    const Program program = Program::fromSources(ShaderSource::fromText(vertex, "maps.vert", {}),
                                                 ShaderSource::fromText(fragment, "maps.frag", {}));
    Framebuffer target(4, 4);
    target.bind();
    glViewport(0, 0, 4, 4);
    auto mesh = std::make_shared<const GpuMesh>(shapes::plane(1.0f, 1));

    Material material;
    material.diffuseMap = (folder / "red.png").string();
    material.specularMap = (folder / "grey.png").string();
    MeshObject textured(mesh, material);
    textured.draw(program);
    const glm::u8vec4 both = target.readColor().pixel(2, 2);
    INFO("with maps: " << describe(both));
    CHECK(test::near(both, {255, 0, 0, 128}, 2));

    MeshObject plain(mesh);
    plain.draw(program);
    const glm::u8vec4 none = target.readColor().pixel(2, 2);
    INFO("without maps: " << describe(none));
    CHECK(test::near(none, {0, 0, 255, 255}, 2));

    // A program that declares none of the map uniforms (labs 01 and 02) draws without a GL error.
    const char* solid = "#version 330 core\nout vec4 fragColor;\nvoid main() { fragColor = vec4(1.0); }\n";
    const Program unaware = Program::fromSources(ShaderSource::fromText(vertex, "maps.vert", {}),
                                                 ShaderSource::fromText(solid, "solid.frag", {}));
    textured.draw(unaware);
    CHECK(glGetError() == GL_NO_ERROR);
    CHECK(TextureCache::shared().aliveCount() >= 2);
}
