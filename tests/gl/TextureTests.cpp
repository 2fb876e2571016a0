#include "GlTestSupport.hpp"
#include "TempFolder.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/gl/VertexArray.hpp>
#include <stoa/image/Image.hpp>

using namespace stoa;
using stoa::test::describe;
using stoa::test::glShadersDir;

namespace {

/// Samples `texture` (on unit 0) at `uv` and returns the colour.
glm::u8vec4 sampleAt(const Texture2D& texture, glm::vec2 uv) {
    const Program program = Program::fromFiles(glShadersDir / "fullscreen.vert", glShadersDir / "sample.frag", {});
    VertexArray empty; // core profile: a vertex array must be bound to draw
    Framebuffer target(2, 2);
    beginPass(passInto(target, RenderState::overlay()));
    texture.bind(0);
    program.use();
    program.set("uTexture", 0);
    program.set("uUv", uv);
    empty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return target.readColor().pixel(1, 1);
}

TextureOptions nearestClamped() {
    TextureOptions options;
    options.mipmaps = false;
    options.wrap = GL_CLAMP_TO_EDGE;
    options.linear = false;
    return options;
}

} // namespace

TEST_CASE("Texture2D: uv (0,0) is the image's bottom-left corner") {
    HeadlessContext context;
    Image image(2, 2, 4);
    image.setPixel(0, 0, {255, 0, 0, 255});     // top-left: red
    image.setPixel(1, 0, {0, 255, 0, 255});     // top-right: green
    image.setPixel(0, 1, {0, 0, 255, 255});     // bottom-left: blue
    image.setPixel(1, 1, {255, 255, 255, 255}); // bottom-right: white
    const Texture2D texture = Texture2D::fromImage(image, nearestClamped());
    CHECK(texture.width() == 2);
    CHECK(texture.height() == 2);
    CHECK(texture.internalFormat() == GL_RGBA8);
    CHECK(sampleAt(texture, {0.25f, 0.25f}) == glm::u8vec4(0, 0, 255, 255));
    CHECK(sampleAt(texture, {0.75f, 0.25f}) == glm::u8vec4(255, 255, 255, 255));
    CHECK(sampleAt(texture, {0.25f, 0.75f}) == glm::u8vec4(255, 0, 0, 255));
    CHECK(sampleAt(texture, {0.75f, 0.75f}) == glm::u8vec4(0, 255, 0, 255));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Texture2D: grey and grey-alpha images sample as grey; RGB rows need no padding") {
    HeadlessContext context;
    SECTION("1 channel -> R8, read as grey with alpha 1") {
        Image grey(1, 1, 1);
        grey.setPixel(0, 0, {100, 100, 100, 255});
        const Texture2D texture = Texture2D::fromImage(grey, nearestClamped());
        CHECK(texture.internalFormat() == GL_R8);
        CHECK(sampleAt(texture, {0.5f, 0.5f}) == glm::u8vec4(100, 100, 100, 255));
    }
    SECTION("2 channels -> RG8, read as grey and alpha") {
        Image greyAlpha(1, 1, 2);
        greyAlpha.setPixel(0, 0, {100, 100, 100, 50});
        const Texture2D texture = Texture2D::fromImage(greyAlpha, nearestClamped());
        CHECK(texture.internalFormat() == GL_RG8);
        CHECK(sampleAt(texture, {0.5f, 0.5f}) == glm::u8vec4(100, 100, 100, 50));
    }
    SECTION("3 channels, 3 pixels wide: 9-byte rows") {
        Image rgb(3, 2, 3);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x)
                rgb.setPixel(x, y, {static_cast<std::uint8_t>(40 * x + 10), static_cast<std::uint8_t>(100 * y + 20), 7, 255});
        const Texture2D texture = Texture2D::fromImage(rgb, nearestClamped());
        CHECK(texture.internalFormat() == GL_RGB8);
        // Texel (2, top row) and (1, bottom row).
        CHECK(sampleAt(texture, {5.0f / 6.0f, 0.75f}) == glm::u8vec4(90, 20, 7, 255));
        CHECK(sampleAt(texture, {0.5f, 0.25f}) == glm::u8vec4(50, 120, 7, 255));
    }
}

TEST_CASE("Texture2D: options choose filtering, wrapping and mipmaps") {
    HeadlessContext context;
    const Image image(4, 4, 4);
    const Texture2D mipmapped = Texture2D::fromImage(image);
    mipmapped.bind(2);
    GLint value = 0;
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &value);
    CHECK(value == GL_LINEAR_MIPMAP_LINEAR);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &value);
    CHECK(value == GL_REPEAT);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 2, GL_TEXTURE_WIDTH, &value);
    CHECK(value == 1); // the chain 4, 2, 1 exists

    const Texture2D plain = Texture2D::fromImage(image, nearestClamped());
    plain.bind(2);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &value);
    CHECK(value == GL_NEAREST);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &value);
    CHECK(value == GL_NEAREST);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &value);
    CHECK(value == GL_CLAMP_TO_EDGE);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
    CHECK(value == GL_TEXTURE2);
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Texture2D: from a file, and a missing file is an InputError") {
    HeadlessContext context;
    test::TempFolder folder("texture-file");
    Image image(3, 1, 3);
    image.setPixel(2, 0, {200, 100, 50, 255});
    image.savePng(folder / "strip.png");
    const Texture2D texture = Texture2D::fromFile(folder / "strip.png", nearestClamped());
    CHECK(texture.width() == 3);
    CHECK(texture.height() == 1);
    CHECK(sampleAt(texture, {5.0f / 6.0f, 0.5f}) == glm::u8vec4(200, 100, 50, 255));

    try {
        Texture2D::fromFile(folder / "missing.png");
        FAIL("a missing texture should throw");
    } catch (const InputError& error) {
        CHECK(error.file().find("missing.png") != std::string::npos);
    }
}

TEST_CASE("Texture2D: empty storage, moves and release") {
    HeadlessContext context;
    Texture2D texture = Texture2D::empty(8, 4, GL_RGBA16F);
    CHECK(texture.width() == 8);
    CHECK(texture.internalFormat() == GL_RGBA16F);
    const GLuint id = texture.id();
    Texture2D moved = std::move(texture);
    CHECK(texture.id() == 0);
    CHECK(moved.id() == id);
    const GLuint released = moved.release();
    CHECK(moved.id() == 0);
    CHECK(glIsTexture(released));
    glDeleteTextures(1, &released);
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Texture2D: creating a texture leaves the texture units' bindings alone") {
    // A lab binds a normal map on unit 2, then MeshObject loads a diffuse map at
    // its first draw: that must not unbind the normal map.
    HeadlessContext context;
    Image pixel(1, 1, 4);
    const Texture2D bound = Texture2D::fromImage(pixel, nearestClamped());
    bound.bind(2);
    const Texture2D fromImage = Texture2D::fromImage(pixel, nearestClamped());
    const Texture2D empty = Texture2D::empty(4, 4, GL_DEPTH_COMPONENT24);
    GLint active = 0, onUnit2 = 0, onUnit0 = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &onUnit2);
    CHECK(active == GL_TEXTURE2);
    CHECK(static_cast<GLuint>(onUnit2) == bound.id());
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &onUnit0);
    CHECK(onUnit0 == 0);
    CHECK(fromImage.id() != bound.id());
    CHECK(empty.id() != 0);
    CHECK(glGetError() == GL_NO_ERROR);
}
