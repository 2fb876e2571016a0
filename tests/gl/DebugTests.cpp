#include "GlTestSupport.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Program.hpp>

#include <cstdio>

using namespace stoa;

namespace {

constexpr GLenum kNotACapability = 0x1234; // glEnable(0x1234): GL_INVALID_ENUM

/// Turns checked mode on for one test and back off after it.
struct CheckedModeOn {
    CheckedModeOn() { setCheckedMode(true); }
    ~CheckedModeOn() { setCheckedMode(false); }
};

std::string readAll(std::FILE* file) {
    std::rewind(file);
    std::string text;
    char buffer[512];
    while (std::size_t count = std::fread(buffer, 1, sizeof buffer, file)) text.append(buffer, count);
    return text;
}

} // namespace

TEST_CASE("Debug: checked mode names the failing call, its file and line") {
    HeadlessContext context;
    CheckedModeOn checked;
    int line = 0;
    try {
        line = __LINE__ + 1;
        STOA_GL_CALL(glEnable(kNotACapability));
        FAIL("glEnable(0x1234) should throw in checked mode");
    } catch (const std::runtime_error& error) {
        CHECK(std::string(error.what()) == "glEnable (DebugTests.cpp:" + std::to_string(line) + "): GL_INVALID_ENUM");
    }
    STOA_GL_CALL(glEnable(GL_DEPTH_TEST)); // a good call passes
    glDisable(GL_DEPTH_TEST);
}

TEST_CASE("Debug: checked mode blames an earlier unchecked call, not the next checked one") {
    HeadlessContext context;
    CheckedModeOn checked;
    glEnable(kNotACapability); // unchecked
    try {
        STOA_GL_CALL(glClear(GL_COLOR_BUFFER_BIT));
        FAIL("the pending error should be reported");
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        CHECK(message.rfind("a GL call before glClear (DebugTests.cpp:", 0) == 0);
        CHECK(message.find("GL_INVALID_ENUM") != std::string::npos);
    }

    glEnable(kNotACapability);
    try {
        STOA_GL_CHECK("after the setup");
        FAIL("STOA_GL_CHECK should report the pending error");
    } catch (const std::runtime_error& error) {
        CHECK(std::string(error.what()).rfind("after the setup (DebugTests.cpp:", 0) == 0);
    }
}

TEST_CASE("Debug: without checked mode nothing is checked") {
    HeadlessContext context;
    setCheckedMode(false);
    CHECK_FALSE(checkedMode());
    STOA_GL_CALL(glEnable(kNotACapability));
    STOA_GL_CHECK("unchecked");
    CHECK(glGetError() == GL_INVALID_ENUM); // still queued
}

TEST_CASE("Debug: the wrappers run their calls checked") {
    HeadlessContext context;
    CheckedModeOn checked;
    SECTION("Buffer::upload with a bad usage") {
        Buffer buffer(GL_ARRAY_BUFFER);
        const float data[2] = {1.0f, 2.0f};
        try {
            buffer.upload(data, sizeof data, GL_TEXTURE_2D);
            FAIL("a bad usage should throw in checked mode");
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            CHECK(message.rfind("glBufferData (Buffer.cpp:", 0) == 0);
            CHECK(message.find("GL_INVALID_ENUM") != std::string::npos);
        }
    }
    SECTION("Program::set with the wrong type names the uniform") {
        const Program program =
            Program::fromFiles(test::glShadersDir / "position2d.vert", test::glShadersDir / "solid.frag", {});
        try {
            program.set("uColor", 1.0f); // uColor is a vec4
            FAIL("a type mismatch should throw in checked mode");
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            CHECK(message.rfind("Program::set(\"uColor\")", 0) == 0);
            CHECK(message.find("GL_INVALID_OPERATION") != std::string::npos);
        }
    }
}

TEST_CASE("Debug: glErrorName") {
    CHECK(std::string(glErrorName(GL_INVALID_OPERATION)) == "GL_INVALID_OPERATION");
    CHECK(std::string(glErrorName(GL_OUT_OF_MEMORY)) == "GL_OUT_OF_MEMORY");
    CHECK(std::string(glErrorName(0x1234)) == "GL error 0x1234");
}

TEST_CASE("Debug: enableDebugOutput prints each driver message once") {
    HeadlessContext context;
    std::FILE* out = std::tmpfile();
    REQUIRE(out != nullptr);
    REQUIRE(enableDebugOutput(out)); // Mesa offers GL_KHR_debug
    glEnable(kNotACapability);
    glEnable(kNotACapability);
    test::takeGlError();
    CHECK_THROWS_AS(Program::fromFiles(test::glShadersDir / "position2d.vert",
                                       test::glShadersDir / "broken_top.frag", {}),
                    ShaderError);
    const std::string printed = readAll(out);
    std::fclose(out);
    enableDebugOutput(stderr);
    INFO(printed);
    const std::size_t first = printed.find("GL API error (high severity)");
    REQUIRE(first != std::string::npos);
    CHECK(printed.find("GL API error", first + 1) == std::string::npos);
    CHECK(printed.find("glEnable") != std::string::npos);
    CHECK(printed.find("undeclaredColor") == std::string::npos); // the ShaderError says it, with the file name
}
