// Issue 10, item 1: passes state their RenderState whole, the StateCache skips
// what would change nothing, wrappers change only their own binding, and
// framebuffers share attachments.

#include "GlTestSupport.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/image/Image.hpp>

#include <glm/vec4.hpp>

using namespace stoa;
using stoa::test::describe;

namespace {

// A clip-space rectangle at depth uDepth (clip z), in colour uColor.
const char* kVertex = "#version 330 core\n"
                      "layout(location = 0) in vec2 aPosition;\n"
                      "uniform float uDepth;\n"
                      "void main() { gl_Position = vec4(aPosition, uDepth, 1.0); }\n";
const char* kFragment = "#version 330 core\n"
                        "uniform vec4 uColor;\n"
                        "out vec4 fragColor;\n"
                        "void main() { fragColor = uColor; }\n";

Program rectangleProgram() {
    return Program::fromSources(ShaderSource::fromText(kVertex, "rectangle.vert", {}),
                                ShaderSource::fromText(kFragment, "rectangle.frag", {}));
}

// Two passes that disagree on everything a RenderState holds.
RenderState additiveOverlay() {
    RenderState state;
    state.depth.test = false;
    state.depth.write = false;
    state.cull = CullMode::Front;    // the clockwise rectangle below is what shows
    state.blend = BlendMode::Additive;
    state.colorMask.green = false;
    return state;
}

RenderState opaqueDepthTested() {
    RenderState state;   // depth test (less), back faces culled, opaque, all channels
    state.stencil.test = true;
    state.stencil.func = GL_ALWAYS;
    state.stencil.pass = GL_INCR;
    return state;
}

// Pass A: additive, into `a`; pass B: depth tested, into `b`. Each draws a
// counter-clockwise and a clockwise rectangle over the same pixels.
void passA(const Framebuffer& a, const Program& program, const test::Triangles2D& ccw, const test::Triangles2D& cw) {
    PassDescription pass = passInto(a, additiveOverlay());
    pass.clear.color = true;
    pass.clear.colorValue = {0.25f, 0.25f, 0.25f, 1.0f};
    beginPass(pass);
    program.use();
    program.set("uDepth", 0.0f);
    program.set("uColor", glm::vec4(0.5f, 0.5f, 0.0f, 0.0f));
    ccw.draw();
    program.set("uColor", glm::vec4(0.0f, 0.5f, 0.5f, 0.0f));
    cw.draw();
}

void passB(const Framebuffer& b, const Program& program, const test::Triangles2D& ccw, const test::Triangles2D& cw) {
    PassDescription pass = passInto(b, opaqueDepthTested());
    pass.clear.color = pass.clear.depth = pass.clear.stencil = true;
    beginPass(pass);
    program.use();
    program.set("uDepth", 0.5f);
    program.set("uColor", glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    ccw.draw();
    program.set("uDepth", 0.75f);   // behind: fails the depth test
    program.set("uColor", glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    ccw.draw();
    cw.draw();   // culled
}

bool samePixels(const Image& x, const Image& y) {
    if (x.width() != y.width() || x.height() != y.height()) return false;
    for (int row = 0; row < x.height(); ++row)
        for (int column = 0; column < x.width(); ++column)
            if (x.pixel(column, row) != y.pixel(column, row)) return false;
    return true;
}

} // namespace

TEST_CASE("RenderState: two passes with different states give the same pictures in either order") {
    HeadlessContext context;
    const Program program = rectangleProgram();
    const test::Triangles2D ccw = test::Triangles2D::rectangle(-0.5f, -0.5f, 0.5f, 0.5f);
    const test::Triangles2D cw({{-0.5f, -0.5f}, {0.5f, 0.5f}, {0.5f, -0.5f}, {-0.5f, -0.5f}, {-0.5f, 0.5f}, {0.5f, 0.5f}});

    Framebuffer a1(8, 8), b1(8, 8), a2(8, 8), b2(8, 8);
    passA(a1, program, ccw, cw);
    passB(b1, program, ccw, cw);
    passB(b2, program, ccw, cw);
    passA(a2, program, ccw, cw);
    const Image imageA = a1.readColor(), imageB = b1.readColor();
    CHECK(samePixels(imageA, a2.readColor()));
    CHECK(samePixels(imageB, b2.readColor()));

    // And the pictures are what the states say: A adds only the clockwise
    // rectangle, without green; B keeps the nearer red one.
    INFO("A centre " << describe(imageA.pixel(4, 4)) << ", B centre " << describe(imageB.pixel(4, 4)));
    CHECK(test::near(imageA.pixel(4, 4), {64, 64, 191, 255}));
    CHECK(test::near(imageA.pixel(0, 0), {64, 64, 64, 255}));
    CHECK(imageB.pixel(4, 4) == glm::u8vec4(255, 0, 0, 255));
    CHECK(imageB.pixel(0, 0) == glm::u8vec4(0, 0, 0, 255));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("StateCache: a state applied again costs no GL call") {
    HeadlessContext context;
    StateCache& cache = StateCache::current();
    cache.apply(additiveOverlay());
    const std::size_t made = cache.callsMade(), skipped = cache.callsSkipped();
    cache.apply(additiveOverlay());
    CHECK(cache.callsMade() == made);
    CHECK(cache.callsSkipped() == skipped + 5);   // depth, cull, blend, colour mask, stencil
    cache.apply(opaqueDepthTested());
    CHECK(cache.callsMade() == made + 5);
    CHECK(glIsEnabled(GL_DEPTH_TEST) == GL_TRUE);
    CHECK(glIsEnabled(GL_BLEND) == GL_FALSE);
    CHECK(glIsEnabled(GL_STENCIL_TEST) == GL_TRUE);

    // After forget() (GL changed behind the cache's back) everything is set again.
    glDisable(GL_DEPTH_TEST);
    cache.forget();
    cache.apply(opaqueDepthTested());
    CHECK(glIsEnabled(GL_DEPTH_TEST) == GL_TRUE);
}

TEST_CASE("Wrappers change only their own binding") {
    HeadlessContext context;
    const Program first = rectangleProgram();
    const Program second = rectangleProgram();
    GLint current = 0;

    SECTION("setting a uniform keeps the program in use") {
        first.use();
        second.set("uDepth", 0.25f);
        glGetIntegerv(GL_CURRENT_PROGRAM, &current);
        CHECK(static_cast<GLuint>(current) == first.id());
        float depth = 0.0f;
        glGetUniformfv(second.id(), second.uniformLocation("uDepth"), &depth);
        CHECK(depth == 0.25f);
    }
    SECTION("binding a framebuffer keeps the viewport") {
        Framebuffer small(4, 4), large(32, 32);
        beginPass(passInto(small));
        large.bind();
        GLint viewport[4];
        glGetIntegerv(GL_VIEWPORT, viewport);
        CHECK(viewport[2] == 4);
        CHECK(viewport[3] == 4);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &current);
        CHECK(static_cast<GLuint>(current) == large.id());
        CHECK(StateCache::current().drawFramebuffer() == large.id());
    }
    SECTION("setAt() asks for the program in use, and sets without a name lookup") {
        second.use();
        second.setAt(second.uniformLocation("uColor"), glm::vec4(0.5f));
        second.setAt(-1, 1.0f);   // a uniform the program does not have: ignored
        CHECK(glGetError() == GL_NO_ERROR);
    }
}

TEST_CASE("Framebuffer: a second framebuffer shares the first's depth-stencil texture") {
    HeadlessContext context;
    const Program program = rectangleProgram();
    FramebufferOptions gBufferOptions;
    gBufferOptions.depthStencilTexture = true;
    Framebuffer gBuffer(8, 8, gBufferOptions);
    REQUIRE(gBuffer.depthTexture() != 0);
    CHECK(gBuffer.depthAttachment()->internalFormat() == GL_DEPTH24_STENCIL8);

    FramebufferOptions lightingOptions;
    lightingOptions.depthAttachment = gBuffer.depthAttachment();
    Framebuffer lighting(8, 8, lightingOptions);
    CHECK(lighting.depthTexture() == gBuffer.depthTexture());

    // The geometry pass writes depth 0.25 (clip z -0.5) over the left half.
    PassDescription geometry = passInto(gBuffer);
    geometry.clear.color = geometry.clear.depth = true;
    beginPass(geometry);
    program.use();
    program.set("uDepth", -0.5f);
    program.set("uColor", glm::vec4(1.0f));
    test::Triangles2D::rectangle(-1.0f, -1.0f, 0.0f, 1.0f).draw();

    // The lighting pass tests against that depth without clearing or writing
    // it: a full-screen rectangle at depth 0.5 shows on the right half only.
    PassDescription light = passInto(lighting);
    light.clear.color = true;
    light.state.depth.write = false;
    beginPass(light);
    program.set("uDepth", 0.0f);
    program.set("uColor", glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    test::Triangles2D::rectangle(-1.0f, -1.0f, 1.0f, 1.0f).draw();

    const Image lit = lighting.readColor();
    INFO("left " << describe(lit.pixel(1, 4)) << ", right " << describe(lit.pixel(6, 4)));
    CHECK(lit.pixel(1, 4) == glm::u8vec4(0, 0, 0, 255));
    CHECK(lit.pixel(6, 4) == glm::u8vec4(0, 255, 0, 255));
    const std::vector<float> depth = lighting.readDepth();
    CHECK(depth[4 * 8 + 1] == Approx(0.25f).margin(1e-3));
    CHECK(depth[4 * 8 + 6] == Approx(1.0f));

    // The texture lives as long as a framebuffer holds it.
    const GLuint texture = gBuffer.depthTexture();
    gBuffer = Framebuffer();
    CHECK(glIsTexture(texture) == GL_TRUE);
    CHECK(lighting.depthTexture() == texture);
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Framebuffer: a shared attachment of the wrong size is refused") {
    HeadlessContext context;
    FramebufferOptions options;
    options.depthTexture = true;
    Framebuffer map(8, 8, options);
    FramebufferOptions sharing;
    sharing.depthAttachment = map.depthAttachment();
    CHECK_THROWS_WITH(Framebuffer(4, 4, sharing), Catch::Contains("attachments must match in size"));
}
