#include "GlTestSupport.hpp"
#include "TempFolder.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/Shader.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/image/Image.hpp>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <chrono>

using namespace stoa;
using stoa::test::describe;
using stoa::test::glShadersDir;
using stoa::test::near;
namespace fs = std::filesystem;

namespace {

std::string normal(const fs::path& path) { return path.lexically_normal().generic_string(); }

/// The colour `program` draws over a 4x4 target, read at its centre.
glm::u8vec4 drawnColour(const Program& program) {
    Framebuffer target(4, 4);
    beginPass(passInto(target, RenderState::overlay()));
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    program.use();
    test::Triangles2D::rectangle(-1.0f, -1.0f, 1.0f, 1.0f).draw();
    return target.readColor().pixel(2, 2);
}

/// Builds the program and returns the ShaderError it threw.
ShaderError shaderErrorOf(const fs::path& vertex, const fs::path& fragment) {
    try {
        Program::fromFiles(vertex, fragment, {});
    } catch (const ShaderError& error) {
        return error;
    }
    FAIL("expected a ShaderError");
    return ShaderError("", 0, "", "");
}

/// Sets a file's modification time one second later than it was, so that a
/// rewrite within the file system's time resolution still counts as a change.
void touchLater(const fs::path& path) {
    fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(1));
}

} // namespace

TEST_CASE("Program: default-constructed GL objects make no GL call (no context needed)") {
    Program program;
    Shader shader;
    Buffer buffer;
    Texture2D texture;
    Framebuffer framebuffer;
    CHECK(program.id() == 0);
    CHECK(shader.id() == 0);
    CHECK(buffer.id() == 0);
    CHECK(texture.id() == 0);
    CHECK(framebuffer.id() == 0);
}

TEST_CASE("Program: built from files, it draws a coloured triangle") {
    HeadlessContext context;
    const Program program = Program::fromFiles(glShadersDir / "position2d.vert", glShadersDir / "solid.frag", {});
    CHECK(program.id() != 0);
    REQUIRE(program.files().size() == 3); // position2d.vert, solid.frag and the included color.glsl
    CHECK(normal(program.files()[2]) == normal(glShadersDir / "color.glsl"));

    program.set("uColor", glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    const glm::u8vec4 colour = drawnColour(program);
    INFO(describe(colour));
    CHECK(colour == glm::u8vec4(0, 255, 0, 255));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Program: a compile error names the file and line, also inside an included file") {
    HeadlessContext context;

    SECTION("in the top file") {
        const ShaderError error = shaderErrorOf(glShadersDir / "position2d.vert", glShadersDir / "broken_top.frag");
        INFO(error.what());
        CHECK(error.file() == normal(glShadersDir / "broken_top.frag"));
        CHECK(error.line() == 7);
        CHECK(error.message().rfind("Program: cannot compile fragment shader ", 0) == 0);
        CHECK(error.log().find(normal(glShadersDir / "broken_top.frag") + ":7: error") != std::string::npos);
    }
    SECTION("in an included file") {
        const ShaderError error =
            shaderErrorOf(glShadersDir / "position2d.vert", glShadersDir / "broken_include.frag");
        INFO(error.what());
        CHECK(error.file() == normal(glShadersDir / "broken_lib.glsl"));
        CHECK(error.line() == 4);
        CHECK(error.message().find(normal(glShadersDir / "broken_lib.glsl") + ":4: error") != std::string::npos);
        CHECK(error.message().find("missingScale") != std::string::npos);
    }
    SECTION("in a vertex shader, caught as the InputError it is") {
        test::TempFolder folder("program-vertex-error");
        test::writeTextFile(folder / "bad.vert", "#version 330 core\n\nvoid main() {\n    gl_Position = nope;\n}\n");
        try {
            Program::fromFiles(folder / "bad.vert", glShadersDir / "solid.frag", {});
            FAIL("the vertex shader should not compile");
        } catch (const InputError& error) {
            CHECK(error.line() == 4);
            CHECK(error.message().rfind("Program: cannot compile vertex shader", 0) == 0);
        }
    }
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Program: a link error says so and carries the log") {
    HeadlessContext context;
    const ShaderError error = shaderErrorOf(glShadersDir / "position2d.vert", glShadersDir / "unlinked.frag");
    INFO(error.what());
    CHECK(error.message().rfind("Program: cannot link " + normal(glShadersDir / "position2d.vert") + " + " +
                                    normal(glShadersDir / "unlinked.frag") + ":",
                                0) == 0);
    CHECK(error.line() == 0);
    CHECK(error.message().find("neverDefined") != std::string::npos);
    CHECK(error.log().find("neverDefined") != std::string::npos);
}

TEST_CASE("Program: a missing shader file is an InputError naming it") {
    HeadlessContext context;
    try {
        Program::fromFiles(glShadersDir / "position2d.vert", "no_such.frag", {glShadersDir});
        FAIL("a missing file should throw");
    } catch (const InputError& error) {
        CHECK(error.file() == "no_such.frag");
        CHECK(error.message().find("cannot find the shader file") != std::string::npos);
    }
}

TEST_CASE("Program: uniform locations are cached; unknown names are ignored") {
    HeadlessContext context;
    const Program program = Program::fromFiles(glShadersDir / "position2d.vert", glShadersDir / "solid.frag", {});
    const GLint location = program.uniformLocation("uColor");
    CHECK(location >= 0);
    CHECK(program.uniformLocation("uColor") == location);
    CHECK(program.uniformLocation("uNotThere") == -1);
    CHECK(program.uniformLocation("uNotThere") == -1);

    program.set("uNotThere", 1.0f);
    program.set("uNotThere", glm::mat4(1.0f));
    CHECK(glGetError() == GL_NO_ERROR);

    program.set("uColor", glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
    glm::vec4 readBack(0.0f);
    glGetUniformfv(program.id(), location, &readBack[0]);
    CHECK(readBack == glm::vec4(0.1f, 0.2f, 0.3f, 0.4f));
}

TEST_CASE("Program: every set() overload reaches its uniform") {
    HeadlessContext context;
    const std::string vertex = "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    const std::string fragment = R"(#version 330 core
uniform int uInt;
uniform uint uUint;
uniform float uFloat;
uniform float uFromDouble;
uniform bool uBool;
uniform vec2 uVec2;
uniform vec3 uVec3;
uniform vec4 uVec4;
uniform mat3 uMat3;
uniform mat4 uMat4;
uniform float uFloats[3];
uniform vec3 uVec3s[2];
uniform vec4 uVec4s[2];
uniform mat4 uMat4s[2];
out vec4 fragColor;
void main() {
    fragColor = vec4(float(uInt) + float(uUint) + uFloat + uFromDouble + (uBool ? 1.0 : 0.0))
              + vec4(uVec2, uVec3.x, 0.0) + uVec4 + vec4(uMat3[0], 0.0) + uMat4[1]
              + vec4(uFloats[2]) + vec4(uVec3s[1], 0.0) + uVec4s[1] + uMat4s[1][2];
}
)";
    const Program program = Program::fromSources(ShaderSource::fromText(vertex, "set.vert", {}),
                                                 ShaderSource::fromText(fragment, "set.frag", {}));
    program.set("uInt", -7);
    program.set("uUint", 7u);
    program.set("uFloat", 0.5f);
    program.set("uFromDouble", 0.25);
    program.set("uBool", true);
    program.set("uVec2", glm::vec2(1.0f, 2.0f));
    program.set("uVec3", glm::vec3(1.0f, 2.0f, 3.0f));
    program.set("uVec4", glm::vec4(1.0f, 2.0f, 3.0f, 4.0f));
    program.set("uMat3", glm::mat3(2.0f));
    program.set("uMat4", glm::mat4(3.0f));
    program.set("uFloats", std::vector<float>{1.0f, 2.0f, 3.0f});
    program.set("uVec3s", std::vector<glm::vec3>{glm::vec3(1.0f), glm::vec3(5.0f, 6.0f, 7.0f)});
    program.set("uVec4s[0]", std::vector<glm::vec4>{glm::vec4(1.0f), glm::vec4(8.0f)});
    program.set("uMat4s", std::vector<glm::mat4>{glm::mat4(1.0f), glm::mat4(9.0f)});
    REQUIRE(glGetError() == GL_NO_ERROR);

    const GLuint id = program.id();
    GLint i = 0;
    GLuint u = 0;
    GLfloat f[16] = {};
    glGetUniformiv(id, program.uniformLocation("uInt"), &i);
    CHECK(i == -7);
    glGetUniformuiv(id, program.uniformLocation("uUint"), &u);
    CHECK(u == 7u);
    glGetUniformfv(id, program.uniformLocation("uFloat"), f);
    CHECK(f[0] == 0.5f);
    glGetUniformfv(id, program.uniformLocation("uFromDouble"), f);
    CHECK(f[0] == 0.25f);
    glGetUniformiv(id, program.uniformLocation("uBool"), &i);
    CHECK(i == 1);
    glGetUniformfv(id, program.uniformLocation("uVec2"), f);
    CHECK((f[0] == 1.0f && f[1] == 2.0f));
    glGetUniformfv(id, program.uniformLocation("uVec3"), f);
    CHECK(f[2] == 3.0f);
    glGetUniformfv(id, program.uniformLocation("uVec4"), f);
    CHECK(f[3] == 4.0f);
    glGetUniformfv(id, program.uniformLocation("uMat3"), f);
    CHECK((f[0] == 2.0f && f[1] == 0.0f && f[4] == 2.0f));
    glGetUniformfv(id, program.uniformLocation("uMat4"), f);
    CHECK((f[5] == 3.0f && f[15] == 3.0f));
    glGetUniformfv(id, program.uniformLocation("uFloats[2]"), f);
    CHECK(f[0] == 3.0f);
    glGetUniformfv(id, program.uniformLocation("uVec3s[1]"), f);
    CHECK((f[0] == 5.0f && f[2] == 7.0f));
    glGetUniformfv(id, program.uniformLocation("uVec4s[1]"), f);
    CHECK(f[3] == 8.0f);
    glGetUniformfv(id, program.uniformLocation("uMat4s[1]"), f);
    CHECK((f[0] == 9.0f && f[10] == 9.0f));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("Program: reloadIfChanged picks up an edit and keeps the old program on a broken one") {
    HeadlessContext context;
    test::TempFolder folder("program-reload");
    const std::string fragment = "#version 330 core\n#include \"colour.glsl\"\nout vec4 fragColor;\n"
                                 "void main() { fragColor = colour(); }\n";
    test::writeTextFile(folder / "shader.frag", fragment);
    test::writeTextFile(folder / "colour.glsl", "vec4 colour() { return vec4(1.0, 0.0, 0.0, 1.0); }\n");
    Program program = Program::fromFiles(glShadersDir / "position2d.vert", folder / "shader.frag", {});
    CHECK(drawnColour(program) == glm::u8vec4(255, 0, 0, 255));
    CHECK_FALSE(program.reloadIfChanged()); // nothing changed
    CHECK(program.lastError().empty());

    // An edit in the included file.
    test::writeTextFile(folder / "colour.glsl", "vec4 colour() { return vec4(0.0, 1.0, 0.0, 1.0); }\n");
    touchLater(folder / "colour.glsl");
    const GLuint before = program.id();
    CHECK(program.reloadIfChanged());
    CHECK(program.lastError().empty());
    CHECK(program.id() != 0);
    CHECK(program.id() != before);
    GLint deleted = GL_TRUE; // the old program is gone (or going, once no longer current)
    if (glIsProgram(before)) glGetProgramiv(before, GL_DELETE_STATUS, &deleted);
    CHECK(deleted == GL_TRUE);
    CHECK(drawnColour(program) == glm::u8vec4(0, 255, 0, 255));

    // A broken edit: the old program stays, the error is kept, and no retry until the next change.
    test::writeTextFile(folder / "colour.glsl", "vec4 colour() {\n    return vec4(0.0, 0.0, 1.0, 1.0)\n}\n");
    touchLater(folder / "colour.glsl");
    const GLuint working = program.id();
    CHECK_FALSE(program.reloadIfChanged());
    INFO(program.lastError());
    CHECK(program.lastError().find("Program: cannot compile fragment shader") != std::string::npos);
    CHECK(program.lastError().find(normal(folder / "colour.glsl") + ":3: error") != std::string::npos);
    CHECK(program.id() == working);
    CHECK(drawnColour(program) == glm::u8vec4(0, 255, 0, 255));
    CHECK_FALSE(program.reloadIfChanged());

    // An edit that adds an include that does not exist yet, then the include appears.
    test::writeTextFile(folder / "shader.frag", "#version 330 core\n#include \"later.glsl\"\nout vec4 fragColor;\n"
                                                "void main() { fragColor = laterColour(); }\n");
    touchLater(folder / "shader.frag");
    CHECK_FALSE(program.reloadIfChanged());
    CHECK(program.lastError().find("cannot find include 'later.glsl'") != std::string::npos);
    CHECK_FALSE(program.reloadIfChanged()); // looked for again, still missing
    test::writeTextFile(folder / "later.glsl", "vec4 laterColour() { return vec4(1.0, 1.0, 0.0, 1.0); }\n");
    CHECK(program.reloadIfChanged());       // found without touching shader.frag again
    CHECK(program.lastError().empty());
    CHECK(drawnColour(program) == glm::u8vec4(255, 255, 0, 255));

    // A later edit of the new include is seen too.
    test::writeTextFile(folder / "later.glsl", "vec4 laterColour() { return vec4(0.0, 1.0, 1.0, 1.0); }\n");
    touchLater(folder / "later.glsl");
    CHECK(program.reloadIfChanged());
    CHECK(drawnColour(program) == glm::u8vec4(0, 255, 255, 255));
}

TEST_CASE("Program: a program from sources has nothing to reload") {
    HeadlessContext context;
    Program program = Program::fromSources(
        ShaderSource::load(glShadersDir / "position2d.vert", {}), ShaderSource::load(glShadersDir / "solid.frag", {}));
    CHECK(program.id() != 0);
    CHECK_FALSE(program.reloadIfChanged());
}

TEST_CASE("Program: STOA_NOT_IMPLEMENTED stubs are listed and compile to their neutral value") {
    HeadlessContext context;
    const Program program = Program::fromFiles(glShadersDir / "position2d.vert", glShadersDir / "stubbed.frag", {});
    REQUIRE(program.stubs().size() == 1);
    CHECK(program.stubs()[0].file == normal(glShadersDir / "stubbed_shading.glsl"));
    CHECK(program.stubs()[0].line == 8);
    CHECK(program.stubs()[0].function == "shade");
    const glm::u8vec4 colour = drawnColour(program);
    INFO(describe(colour));
    CHECK(near(colour, {64, 128, 191, 255}));

    const Program complete = Program::fromFiles(glShadersDir / "position2d.vert", glShadersDir / "solid.frag", {});
    CHECK(complete.stubs().empty());
}

TEST_CASE("Program: a geometry shader stage") {
    HeadlessContext context;
    test::TempFolder folder("program-geometry");
    test::writeTextFile(folder / "pass.geom", R"(#version 330 core
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
)");
    const Program program = Program::fromFiles(glShadersDir / "position2d.vert", folder / "pass.geom",
                                               glShadersDir / "solid.frag", {});
    CHECK(program.files().size() == 4);
    program.set("uColor", glm::vec4(1.0f, 0.0f, 1.0f, 1.0f));
    CHECK(drawnColour(program) == glm::u8vec4(255, 0, 255, 255));
}

TEST_CASE("Program: move and release hand the GL program over") {
    HeadlessContext context;
    Program program = Program::fromFiles(glShadersDir / "position2d.vert", glShadersDir / "solid.frag", {});
    const GLuint id = program.id();
    Program moved(std::move(program));
    CHECK(program.id() == 0);
    CHECK(moved.id() == id);
    CHECK(moved.uniformLocation("uColor") >= 0);

    Program assigned;
    assigned = std::move(moved);
    CHECK(assigned.id() == id);
    const GLuint released = assigned.release();
    CHECK(released == id);
    CHECK(assigned.id() == 0);
    CHECK(glIsProgram(released));
    glDeleteProgram(released);
}
