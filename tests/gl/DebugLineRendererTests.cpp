// DebugLineRenderer: lines in their colour where the camera puts them.

#include "GlTestSupport.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/DebugLines.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/render/DebugLineRenderer.hpp>

using namespace stoa;

TEST_CASE("DebugLineRenderer: a segment draws in its colour where the camera sees it, and nowhere else") {
    HeadlessContext context;
    const Program program = Program::fromFiles("debug/lines.vert", "debug/lines.frag", {paths::shadersDir()});
    DebugLineRenderer renderer(program);
    DebugLines lines;
    lines.line({-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {1.0f, 0.5f, 0.0f});   // across the middle row
    Framebuffer target(16, 16);
    PassDescription pass = passInto(target, RenderState::overlay());
    pass.clear.color = true;
    beginPass(pass);
    renderer.draw(lines, glm::mat4(1.0f));   // clip space = world space
    const Image picture = target.readColor();
    int lit = 0;
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            const glm::u8vec4 pixel = picture.pixel(x, y);
            if (pixel.r == 0) continue;
            ++lit;
            CHECK((y == 7 || y == 8));   // the middle row of 16 (the line's row is a rounding choice)
            CHECK(test::near(pixel, {255, 128, 0, 255}, 2));
        }
    }
    CHECK(lit >= 14);   // the whole width, give or take the ends
    CHECK(lit <= 32);
}
