#include "GlTestSupport.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/image/Image.hpp>

#include <glm/vec4.hpp>

using namespace stoa;
using stoa::test::describe;
using stoa::test::near;

TEST_CASE("Framebuffer: a clear reads back as the clear colour, RGBA") {
    HeadlessContext context;
    Framebuffer target(8, 6);
    CHECK(target.width() == 8);
    CHECK(target.height() == 6);
    CHECK(target.colorTexture() != 0);
    CHECK(target.depthTexture() == 0);
    target.bind();
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const Image image = target.readColor();
    REQUIRE(image.width() == 8);
    REQUIRE(image.height() == 6);
    REQUIRE(image.channels() == 4);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            INFO("pixel " << x << "," << y << " " << describe(image.pixel(x, y)));
            CHECK(near(image.pixel(x, y), {64, 128, 191, 255}));
        }
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Framebuffer: readColor returns the top row first") {
    HeadlessContext context;
    const Program program =
        Program::fromFiles(test::glShadersDir / "position2d.vert", test::glShadersDir / "solid.frag", {});
    const test::Triangles2D topHalf = test::Triangles2D::rectangle(-1.0f, 0.0f, 1.0f, 1.0f); // clip y > 0: the top
    Framebuffer target(16, 16);
    beginPass(passInto(target, RenderState::overlay()));
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    program.use();
    program.set("uColor", glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    topHalf.draw();
    const Image image = target.readColor();
    for (int y = 0; y < 16; ++y) {
        const glm::u8vec4 expected = y < 8 ? glm::u8vec4(255, 0, 0, 255) : glm::u8vec4(0, 0, 0, 255);
        INFO("row " << y << ": " << describe(image.pixel(5, y)));
        CHECK(image.pixel(5, y) == expected);
    }
}

TEST_CASE("Framebuffer: depth as a texture, without colour (a shadow map)") {
    HeadlessContext context;
    FramebufferOptions options;
    options.color = false;
    options.depthTexture = true;
    Framebuffer shadowMap(8, 8, options);
    CHECK(shadowMap.colorTexture() == 0);
    CHECK(shadowMap.depthTexture() != 0);

    const Program program =
        Program::fromFiles(test::glShadersDir / "position2d.vert", test::glShadersDir / "solid.frag", {});
    const test::Triangles2D topHalf = test::Triangles2D::rectangle(-1.0f, 0.0f, 1.0f, 1.0f);
    PassDescription pass;
    pass.target = &shadowMap;
    pass.clear.depth = true;
    pass.state.cull = CullMode::None;
    beginPass(pass);
    program.use();
    topHalf.draw(); // z = 0 in clip space: window depth 0.5
    const std::vector<float> depth = shadowMap.readDepth();
    REQUIRE(depth.size() == 64);
    CHECK(depth[0 * 8 + 3] == Approx(0.5f).margin(1e-4)); // top row
    CHECK(depth[7 * 8 + 3] == Approx(1.0f));              // bottom row
    shadowMap.bindDepthTexture(3);
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    CHECK(static_cast<GLuint>(bound) == shadowMap.depthTexture());
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Framebuffer: several colour targets, integer ones read with readPixels (picking IDs)") {
    HeadlessContext context;
    FramebufferOptions options;
    options.colorFormats = {GL_RGBA8, GL_R32UI};
    Framebuffer target(4, 4, options);
    CHECK(target.colorTexture(0) != 0);
    CHECK(target.colorTexture(1) != 0);
    CHECK(target.colorTexture(2) == 0);
    target.bind();
    const GLfloat colour[4] = {0.0f, 0.0f, 1.0f, 1.0f};
    const GLuint id[4] = {123456789u, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, colour);
    glClearBufferuiv(GL_COLOR, 1, id);
    GLuint picked = 0;
    target.readPixels(1, 2, 1, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &picked);
    CHECK(picked == 123456789u);
    CHECK(target.readColor(0).pixel(0, 0) == glm::u8vec4(0, 0, 255, 255));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Framebuffer: an impossible combination throws naming the status") {
    HeadlessContext context;
    FramebufferOptions options;
    options.colorFormats = {GL_DEPTH_COMPONENT24}; // a depth format is no colour attachment
    try {
        Framebuffer target(4, 4, options);
        FAIL("an incomplete framebuffer should throw");
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        INFO(message);
        CHECK(message.find("GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT") != std::string::npos);
        CHECK(message.rfind("Framebuffer(4x4)", 0) == 0);
    }
    test::takeGlError();
}

TEST_CASE("Framebuffer: creation keeps the bound framebuffer; moves hand the objects over") {
    HeadlessContext context;
    Framebuffer first(4, 4);
    first.bind();
    Framebuffer second(2, 2);
    GLint bound = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    CHECK(static_cast<GLuint>(bound) == first.id());

    const GLuint id = second.id();
    const GLuint colour = second.colorTexture();
    Framebuffer moved(std::move(second));
    CHECK(second.id() == 0);
    CHECK(moved.id() == id);
    CHECK(moved.colorTexture() == colour);
    CHECK(moved.width() == 2);
    {
        Framebuffer scoped = std::move(moved);
        CHECK(glIsFramebuffer(id));
    }
    CHECK_FALSE(glIsFramebuffer(id));
    CHECK_FALSE(glIsTexture(colour));
    Framebuffer::bindDefault();
}
