// Lab 05 on the GPU: the student's depth pass (shadow_pass.cpp) against a light
// matrix built here with glm, and the functions of shadows.glsl evaluated in a
// fragment shader against the same formulas in C++ (docs/labs/05_shadows.md).
// Each test makes its own headless context.

#include "catch.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/gl/VertexArray.hpp>
#include <stoa/image/Image.hpp>
#include "lab05.hpp"
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace {

// Looking straight down from y = 5 over [-2, 2]^2, depth range 0..10: a plane at
// height h has window depth (5 - h) / 10.
glm::mat4 overheadLight() {
    return glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.0f, 10.0f) *
           glm::lookAt(glm::vec3(0.0f, 5.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
}

stoa::FramebufferOptions depthOnly() {
    stoa::FramebufferOptions options;
    options.color = false;
    options.depthTexture = true;
    return options;
}

// Every value within `epsilon` of `expected`; reports the first that is not.
void requireAll(const std::vector<float>& values, float expected, float epsilon = 1e-3f) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (std::abs(values[i] - expected) > epsilon) {
            CAPTURE(i, values[i], expected);
            FAIL("depth texel differs");
        }
    }
    SUCCEED();
}

// Evaluates GLSL `expression` (a vec4) with shadows.glsl of the solutions
// included, on one pixel of a float target. `map`, when given, is `uMap`.
glm::vec4 evaluate(const std::string& expression, const stoa::Texture2D* map = nullptr) {
    const std::vector<std::filesystem::path> searchPath{stoa::paths::sourceDir() / "solutions",
                                                        stoa::paths::shadersDir()};
    const std::string vertex = "#version 330 core\n"
                               "void main() {\n"
                               "    vec2 corner = vec2((gl_VertexID & 1) * 4.0 - 1.0, (gl_VertexID >> 1) * 4.0 - 1.0);\n"
                               "    gl_Position = vec4(corner, 0.0, 1.0);\n"
                               "}\n";
    const std::string fragment = "#version 330 core\n"
                                 "#include \"05_shadows/student/shadows.glsl\"\n"
                                 "uniform sampler2D uMap;\n"
                                 "out vec4 result;\n"
                                 "void main() { result = vec4(" + expression + "); }\n";
    const stoa::Program program = stoa::Program::fromSources(stoa::ShaderSource::fromText(vertex, "test.vert", searchPath),
                                                             stoa::ShaderSource::fromText(fragment, "test.frag", searchPath));
    stoa::FramebufferOptions options;
    options.colorFormats = {GL_RGBA32F};
    stoa::Framebuffer target(1, 1, options);
    target.bind();
    program.use();   // set() skips a uniform the compiler dropped, and then binds nothing
    program.set("uMap", 0);
    if (map) map->bind(0);   // after the target: creating its texture used unit 0
    stoa::VertexArray vertexArray;
    vertexArray.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glm::vec4 value;
    target.readPixels(0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, &value[0]);
    return value;
}

std::string glsl(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    std::string result = text;
    if (result.find_first_of(".e") == std::string::npos) result += ".0";
    return result;
}

std::string glsl(const glm::mat4& m) {
    std::string text = "mat4(";
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) text += glsl(m[c][r]) + (c == 3 && r == 3 ? ")" : ", ");
    return text;
}

} // namespace

TEST_CASE("renderShadowPass fills the whole map with the depth seen from the light") {
    stoa::HeadlessContext context;
    const stoa::Program depth = stoa::Program::fromFiles("shadows/depth.vert", "shadows/depth.frag", {stoa::paths::shadersDir()});
    stoa::Scene scene;
    auto& plane = scene.add(std::make_unique<stoa::MeshObject>(std::make_shared<const stoa::GpuMesh>(stoa::shapes::plane(1.0f, 1))));
    plane.position = {0.0f, 1.0f, 0.0f};
    plane.scale = {4.0f, 1.0f, 4.0f};   // covers the light's whole box

    stoa::Framebuffer map(64, 64, depthOnly());
    stoa::Framebuffer elsewhere(16, 16);
    stoa::beginPass(stoa::passInto(elsewhere));   // the viewport is 16x16 now: the pass must set the map's own

    stoa::renderShadowPass(scene, map, depth, overheadLight());
    requireAll(map.readDepth(), 0.4f);
    // Nothing to turn back on: the lit pass states its own RenderState.

    SECTION("a later pass clears the map and draws faces turned away from the light") {
        plane.position.y = 0.0f;               // further away: without a clear the old 0.4 would stay
        plane.rotationDegrees.x = 180.0f;      // facing down: back-face culling would drop it
        stoa::renderShadowPass(scene, map, depth, overheadLight());
        requireAll(map.readDepth(), 0.5f);
    }
}

TEST_CASE("shadowMapCoordinates maps the light's clip space to texture space") {
    stoa::HeadlessContext context;
    const glm::mat4 matrices[] = {overheadLight(),
                                  glm::perspective(glm::radians(70.0f), 1.0f, 0.5f, 30.0f) *
                                      glm::lookAt(glm::vec3(3.0f, 8.0f, 2.0f), glm::vec3(0.0f), glm::vec3(0, 1, 0))};
    const glm::vec3 point(0.7f, 0.4f, -1.1f);
    for (const glm::mat4& matrix : matrices) {
        const glm::vec4 clip = matrix * glm::vec4(point, 1.0f);
        const glm::vec3 expected = glm::vec3(clip) / clip.w * 0.5f + 0.5f;
        const glm::vec4 got = evaluate("shadowMapCoordinates(" + glsl(matrix) + ", vec3(" + glsl(point.x) + ", " +
                                       glsl(point.y) + ", " + glsl(point.z) + ")), 0.0");
        CHECK(got.x == Approx(expected.x).margin(1e-5));
        CHECK(got.y == Approx(expected.y).margin(1e-5));
        CHECK(got.z == Approx(expected.z).margin(1e-5));
    }
}

TEST_CASE("slopeScaledBias grows with tan(theta) between its minimum and maximum") {
    stoa::HeadlessContext context;
    const glm::vec3 bias(0.002f, 0.0005f, 0.01f);
    const std::string biasText = "vec3(0.002, 0.0005, 0.01)";
    // Facing the light: tan 0 = 0, raised to the minimum.
    CHECK(evaluate("slopeScaledBias(1.0, " + biasText + "), 0.0, 0.0, 0.0").x == Approx(bias.y).margin(1e-7));
    // 60 degrees: 0.002 tan 60.
    CHECK(evaluate("slopeScaledBias(0.5, " + biasText + "), 0.0, 0.0, 0.0").x ==
          Approx(bias.x * std::tan(std::acos(0.5f))).margin(1e-6));
    // Grazing: capped at the maximum.
    CHECK(evaluate("slopeScaledBias(0.05, " + biasText + "), 0.0, 0.0, 0.0").x == Approx(bias.z).margin(1e-7));
    CHECK(evaluate("slopeScaledBias(0.0, " + biasText + "), 0.0, 0.0, 0.0").x == Approx(bias.z).margin(1e-7));
}

TEST_CASE("umbraShade is eq. 4 of Velazquez-Armendariz and Millan (2006)") {
    stoa::HeadlessContext context;
    for (const float s : {0.0f, 0.5f, 1.0f}) {
        const glm::vec4 got = evaluate("umbraShade(vec3(0.1, 0.05, 0.0), vec3(0.6, 0.4, 0.2), " + glsl(s) + "), 0.0");
        CAPTURE(s);
        CHECK(got.x == Approx(0.1f + 0.5f * (1.0f + s) * 0.6f).margin(1e-6));
        CHECK(got.y == Approx(0.05f + 0.5f * (1.0f + s) * 0.4f).margin(1e-6));
        CHECK(got.z == Approx(0.5f * (1.0f + s) * 0.2f).margin(1e-6));
    }
}

TEST_CASE("shadowFactor: single tap, 2x2 and 3x3 PCF over texels, lit outside the map") {
    stoa::HeadlessContext context;
    // An 8x8 map: columns 0-3 hold an occluder at depth 0.2, columns 4-7 nothing (1.0).
    stoa::Image image(8, 8, 1);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const std::uint8_t value = x < 4 ? 51 : 255;
            image.setPixel(x, y, {value, value, value, 255});
        }
    stoa::TextureOptions options;
    options.mipmaps = false;
    options.linear = false;
    options.wrap = GL_CLAMP_TO_EDGE;
    const stoa::Texture2D map = stoa::Texture2D::fromImage(image, options);

    // A receiver at depth 0.5, bias 0.001; u is given in texels (texel x spans [x, x + 1]).
    const auto factor = [&map](float uTexels, float vTexels, int mode, float depth = 0.5f) {
        return evaluate("shadowFactor(uMap, vec3(" + glsl(uTexels / 8.0f) + ", " + glsl(vTexels / 8.0f) + ", " +
                        glsl(depth) + "), 0.001, " + std::to_string(mode) + "), 0.0, 0.0, 0.0", &map)
            .x;
    };
    CHECK(factor(1.5f, 3.5f, 0) == Approx(0.0f));          // behind the occluder
    CHECK(factor(6.5f, 3.5f, 0) == Approx(1.0f));          // nothing in front
    CHECK(factor(0.5f, 3.5f, 0, 0.15f) == Approx(1.0f));   // in front of the occluder
    CHECK(factor(4.0f, 4.0f, 1) == Approx(0.5f));          // 2x2 on the edge: 2 of 4 texels lit
    CHECK(factor(4.5f, 4.5f, 2) == Approx(6.0f / 9.0f));   // 3x3: columns 3, 4, 5
    CHECK(factor(3.5f, 4.5f, 2) == Approx(3.0f / 9.0f));   // 3x3: columns 2, 3, 4
    CHECK(factor(1.5f, 4.5f, 2) == Approx(0.0f));          // 3x3 wholly behind the occluder
    // Outside the map's sides or beyond its far plane: lit.
    CHECK(factor(-2.0f, 3.5f, 0) == Approx(1.0f));
    CHECK(factor(1.5f, 9.0f, 2) == Approx(1.0f));
    CHECK(factor(1.5f, 3.5f, 1, 1.2f) == Approx(1.0f));
}
