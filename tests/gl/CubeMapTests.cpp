// CubeMap: the faces land where the OpenGL spec's cube-map table says a
// direction looks them up, with their rows the right way up.

#include "GlTestSupport.hpp"
#include "TempFolder.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/gl/CubeMap.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/VertexArray.hpp>
#include <stoa/image/Image.hpp>

#include <glm/vec3.hpp>

using namespace stoa;
using stoa::test::describe;

namespace {

const char* kVertex = "#version 330 core\n"
                      "void main() {\n"
                      "    vec2 corner = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);\n"
                      "    gl_Position = vec4(corner, 0.0, 1.0);\n"
                      "}\n";
const char* kFragment = "#version 330 core\n"
                        "uniform samplerCube uSky;\n"
                        "uniform vec3 uDirection;\n"
                        "out vec4 fragColor;\n"
                        "void main() { fragColor = texture(uSky, uDirection); }\n";

// Texel (column, row) of face `face`, row 0 at the top of its Image.
glm::u8vec4 texelColor(int face, int column, int row) {
    return {static_cast<std::uint8_t>(30 + face * 40), static_cast<std::uint8_t>(column ? 220 : 20),
            static_cast<std::uint8_t>(row ? 220 : 20), 255};
}

std::array<Image, 6> labelledFaces() {
    std::array<Image, 6> faces;
    for (int face = 0; face < 6; ++face) {
        Image image(2, 2, 4);
        for (int row = 0; row < 2; ++row)
            for (int column = 0; column < 2; ++column) image.setPixel(column, row, texelColor(face, column, row));
        faces[static_cast<std::size_t>(face)] = std::move(image);
    }
    return faces;
}

// The direction whose look-up lands on (sc, tc) in [-1, 1] of `face`: the spec's
// table (major axis, sc, tc per face) solved for the direction with |ma| = 1.
glm::vec3 directionFor(int face, float sc, float tc) {
    switch (face) {
    case 0: return {1.0f, -tc, -sc};    // +X: sc = -rz, tc = -ry
    case 1: return {-1.0f, -tc, sc};    // -X: sc = +rz, tc = -ry
    case 2: return {sc, 1.0f, tc};      // +Y: sc = +rx, tc = +rz
    case 3: return {sc, -1.0f, -tc};    // -Y: sc = +rx, tc = -rz
    case 4: return {sc, -tc, 1.0f};     // +Z: sc = +rx, tc = -ry
    default: return {-sc, -tc, -1.0f};  // -Z: sc = -rx, tc = -ry
    }
}

} // namespace

TEST_CASE("CubeMap: each direction reads the face and texel the spec's table gives") {
    HeadlessContext context;
    const CubeMap sky = CubeMap::fromImages(labelledFaces());
    CHECK(sky.size() == 2);
    const Program program = Program::fromSources(ShaderSource::fromText(kVertex, "sky_test.vert", {}),
                                                 ShaderSource::fromText(kFragment, "sky_test.frag", {}));
    VertexArray empty;
    Framebuffer target(1, 1);
    for (int face = 0; face < 6; ++face) {
        for (int row = 0; row < 2; ++row) {
            for (int column = 0; column < 2; ++column) {
                // The centre of texel (column, row): s, t = 0.25 or 0.75; the face's row 0 is t < 0.5.
                const float sc = column ? 0.5f : -0.5f;
                const float tc = row ? 0.5f : -0.5f;
                beginPass(passInto(target, RenderState::overlay()));
                sky.bind(0);
                program.use();
                program.set("uSky", 0);
                program.set("uDirection", directionFor(face, sc, tc));
                empty.bind();
                glDrawArrays(GL_TRIANGLES, 0, 3);
                const glm::u8vec4 got = target.readColor().pixel(0, 0);
                INFO("face " << CubeMap::kFaceNames[static_cast<std::size_t>(face)] << " texel " << column << ","
                             << row << ": got " << describe(got) << ", expected "
                             << describe(texelColor(face, column, row)));
                CHECK(test::near(got, texelColor(face, column, row), 2));
            }
        }
    }
}

TEST_CASE("CubeMap: faces that are not square, differ in size or are missing are named") {
    HeadlessContext context;
    std::array<Image, 6> faces = labelledFaces();
    faces[3] = Image(2, 3, 4);
    try {
        CubeMap::fromImages(faces, "sky");
        FAIL("a 2x3 face was accepted");
    } catch (const InputError& error) {
        CHECK(error.file() == "sky face ny");
        CHECK(std::string(error.what()).find("square") != std::string::npos);
    }
    faces = labelledFaces();
    faces[5] = Image(4, 4, 4);
    CHECK_THROWS_AS(CubeMap::fromImages(faces, "sky"), InputError);

    stoa::test::TempFolder folder;
    faces = labelledFaces();
    for (std::size_t i = 0; i < 5; ++i) faces[i].savePng(folder.path() / (std::string(CubeMap::kFaceNames[i]) + ".png"));
    try {
        CubeMap::fromFolder(folder.path());   // nz.png is missing
        FAIL("a folder without nz.png was accepted");
    } catch (const InputError& error) {
        CHECK(error.file().find("nz.png") != std::string::npos);
    }
    faces[5].savePng(folder.path() / "nz.png");
    CHECK(CubeMap::fromFolder(folder.path()).size() == 2);
}

TEST_CASE("CubeMap: the committed sky loads, and straight up reads the sky's blue") {
    HeadlessContext context;
    const CubeMap sky = CubeMap::fromFolder(paths::assetsDir() / "sky");
    CHECK(sky.size() == 128);
    const Program program = Program::fromSources(ShaderSource::fromText(kVertex, "sky_test.vert", {}),
                                                 ShaderSource::fromText(kFragment, "sky_test.frag", {}));
    VertexArray empty;
    Framebuffer target(1, 1);
    beginPass(passInto(target, RenderState::overlay()));
    sky.bind(0);
    program.use();
    program.set("uSky", 0);
    program.set("uDirection", glm::vec3(0.0f, 1.0f, 0.0f));
    empty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    const glm::u8vec4 zenith = target.readColor().pixel(0, 0);
    INFO("straight up: " << describe(zenith));
    CHECK(zenith.b > zenith.r + 60);
}
