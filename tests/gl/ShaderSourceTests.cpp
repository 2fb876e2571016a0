// ShaderSource: #include expansion, #line mapping, log translation and stub
// listing. No GL context: these run in stoa-tests-core.
#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/gl/ShaderSource.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

using namespace stoa;
namespace fs = std::filesystem;

namespace {

const fs::path resolveDir = fs::path(STOA_TEST_DATA_DIR) / "gl" / "resolve";
const fs::path shadersDir = fs::path(STOA_TEST_DATA_DIR) / "gl" / "shaders";

void writeFile(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::string normal(const fs::path& path) { return path.lexically_normal().generic_string(); }

/// Runs `load` and returns the InputError it threw (fails the test if none).
template <typename Load>
InputError errorOf(Load load) {
    try {
        load();
    } catch (const InputError& error) {
        return error;
    }
    FAIL("expected an InputError");
    return InputError("", 0, "");
}

/// Checks that origin() maps every line of the expanded text to the line of
/// the file it was copied from.
void checkLineMapping(const ShaderSource& source) {
    std::vector<std::vector<std::string>> fileLines;
    for (const fs::path& file : source.files()) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        fileLines.push_back(linesOf(text.str()));
    }
    const std::vector<std::string> expanded = linesOf(source.text());
    CHECK_FALSE(source.origin(0));
    CHECK_FALSE(source.origin(static_cast<int>(expanded.size()) + 1));
    int copied = 0;
    for (int i = 1; i <= static_cast<int>(expanded.size()); ++i) {
        const std::optional<ShaderLocation> origin = source.origin(i);
        REQUIRE(origin);
        std::size_t file = 0;
        while (file < source.files().size() && normal(source.files()[file]) != origin->file) ++file;
        REQUIRE(file < fileLines.size());
        REQUIRE(origin->line >= 1);
        REQUIRE(origin->line <= static_cast<int>(fileLines[file].size()));
        const std::string& original = fileLines[file][static_cast<std::size_t>(origin->line - 1)];
        const std::string& line = expanded[static_cast<std::size_t>(i - 1)];
        INFO("expanded line " << i << " from " << origin->file << ":" << origin->line);
        if (line.rfind("#define STOA_NOT_IMPLEMENTED", 0) == 0) {
            CHECK(original.find("#version") != std::string::npos); // the inserted line counts as #version's
        } else if (line.empty() && original.find("#include") != std::string::npos) {
            // a repeated include, expanded once only
        } else {
            CHECK(line == original);
            ++copied;
        }
    }
    CHECK(copied > 0);
}

} // namespace

TEST_CASE("ShaderSource: includes are found next to the including file, then along the search path in order") {
    const ShaderSource source =
        ShaderSource::load(resolveDir / "main" / "top.frag", {resolveDir / "first", resolveDir / "second"});
    const std::vector<fs::path>& files = source.files();
    REQUIRE(files.size() == 5);
    CHECK(normal(files[0]) == normal(resolveDir / "main/top.frag"));
    CHECK(normal(files[1]) == normal(resolveDir / "main/local.glsl"));       // next to top.frag beats first/
    CHECK(normal(files[2]) == normal(resolveDir / "first/shared.glsl"));     // first/ beats second/
    CHECK(normal(files[3]) == normal(resolveDir / "second/second_only.glsl"));
    CHECK(normal(files[4]) == normal(resolveDir / "second/helper.glsl"));    // next to second_only beats first/
    CHECK(source.text().find("localFrom = 0") != std::string::npos);
    CHECK(source.text().find("localFrom = 1") == std::string::npos);
    CHECK(source.text().find("sharedFrom = 2") == std::string::npos);
    CHECK(source.text().find("helperFrom = 2") != std::string::npos);
}

TEST_CASE("ShaderSource: the top file is found as given or along the search path") {
    const ShaderSource direct = ShaderSource::load(shadersDir / "solid.frag", {});
    const ShaderSource searched = ShaderSource::load("solid.frag", {resolveDir, shadersDir});
    CHECK(normal(searched.files()[0]) == normal(shadersDir / "solid.frag"));
    CHECK(direct.text() == searched.text());

    const InputError error = errorOf([&] { ShaderSource::load("no_such.frag", {resolveDir, shadersDir}); });
    CHECK(error.file() == "no_such.frag");
    CHECK(error.line() == 0);
    CHECK(error.message().find("cannot find the shader file") != std::string::npos);
    CHECK(error.message().find(normal(shadersDir)) != std::string::npos);
}

TEST_CASE("ShaderSource: a file included twice is expanded once") {
    test::TempFolder folder("shader-once");
    writeFile(folder / "top.frag", "#version 330 core\n#include \"a.glsl\"\n#include \"b.glsl\"\n#include \"a.glsl\"\n");
    writeFile(folder / "a.glsl", "const int fromA = 1;\n");
    writeFile(folder / "b.glsl", "#include \"a.glsl\"\nconst int fromB = 2;\n");
    const ShaderSource source = ShaderSource::load(folder / "top.frag", {});
    CHECK(source.files().size() == 3);
    const std::string& text = source.text();
    const std::size_t first = text.find("fromA");
    REQUIRE(first != std::string::npos);
    CHECK(text.find("fromA", first + 1) == std::string::npos);
    CHECK(text.find("fromB") != std::string::npos);
    checkLineMapping(source);
}

TEST_CASE("ShaderSource: an include cycle is an error naming the chain") {
    test::TempFolder folder("shader-cycle");
    writeFile(folder / "top.frag", "#version 330 core\n#include \"a.glsl\"\nvoid main() {}\n");
    writeFile(folder / "a.glsl", "// a\n#include \"b.glsl\"\n");
    writeFile(folder / "b.glsl", "// b\n\n#include \"a.glsl\"\n");
    const InputError error = errorOf([&] { ShaderSource::load(folder / "top.frag", {}); });
    CHECK(error.file() == normal(folder / "b.glsl"));
    CHECK(error.line() == 3);
    CHECK(error.message().find("include cycle") != std::string::npos);
    CHECK(error.message().find("a.glsl -> ") != std::string::npos);
    CHECK(error.message().find("b.glsl -> ") != std::string::npos);

    writeFile(folder / "self.frag", "#version 330 core\n#include \"self.frag\"\n");
    const InputError self = errorOf([&] { ShaderSource::load(folder / "self.frag", {}); });
    CHECK(self.line() == 2);
    CHECK(self.message().find("include cycle") != std::string::npos);
}

TEST_CASE("ShaderSource: a missing include names the including file, its line and the folders searched") {
    test::TempFolder folder("shader-missing");
    writeFile(folder / "top.frag", "#version 330 core\n#include \"lib/helper.glsl\"\n");
    writeFile(folder / "lib" / "helper.glsl", "// helper\n\n#include \"nowhere.glsl\"\n");
    const InputError error = errorOf([&] { ShaderSource::load(folder / "top.frag", {resolveDir / "first", resolveDir / "second"}); });
    CHECK(error.file() == normal(folder / "lib/helper.glsl"));
    CHECK(error.line() == 3);
    CHECK(error.message() == "cannot find include 'nowhere.glsl' (searched: " + normal(folder / "lib") + ", " +
                                 normal(resolveDir / "first") + ", " + normal(resolveDir / "second") + ")");
    CHECK(std::string(error.what()).rfind(normal(folder / "lib/helper.glsl") + ":3: cannot find include", 0) == 0);
}

TEST_CASE("ShaderSource: a malformed #include is an error") {
    test::TempFolder folder("shader-malformed");
    writeFile(folder / "top.frag", "#version 330 core\n\n#include <angle.glsl>\n");
    const InputError error = errorOf([&] { ShaderSource::load(folder / "top.frag", {}); });
    CHECK(error.line() == 3);
    CHECK(error.message().find("expected #include \"name\"") != std::string::npos);
}

TEST_CASE("ShaderSource: a /* comment left open in a file is an error") {
    test::TempFolder folder("shader-comment");
    writeFile(folder / "top.frag", "#version 330 core\n#include \"lib.glsl\"\nvoid main() {}\n");
    writeFile(folder / "lib.glsl", "/* closed */\nfloat f() { return 1.0; } /* open\n  still open\n");
    const InputError error = errorOf([&] { ShaderSource::load(folder / "top.frag", {}); });
    CHECK(error.file() == normal(folder / "lib.glsl"));
    CHECK(error.line() == 2);
    CHECK(error.message().find("never closed") != std::string::npos);
}

TEST_CASE("ShaderSource: #version must open the top file and only the top file") {
    test::TempFolder folder("shader-version");

    SECTION("comments and blank lines may precede it") {
        writeFile(folder / "ok.frag", "// header\n/* a block\n   comment */\n\n#version 330 core\nvoid main() {}\n");
        const ShaderSource source = ShaderSource::load(folder / "ok.frag", {});
        const std::vector<std::string> lines = linesOf(source.text());
        REQUIRE(lines.size() == 7);
        CHECK(lines[4] == "#version 330 core");
        CHECK(lines[5] == "#define STOA_NOT_IMPLEMENTED(value) (value)"); // right after #version
        CHECK(source.origin(6)->line == 5);
        CHECK(source.origin(7)->line == 6);
        checkLineMapping(source);
    }
    SECTION("code before it") {
        writeFile(folder / "late.frag", "// header\nuniform float x;\n#version 330 core\n");
        const InputError error = errorOf([&] { ShaderSource::load(folder / "late.frag", {}); });
        CHECK(error.file() == normal(folder / "late.frag"));
        CHECK(error.line() == 2);
        CHECK(error.message().find("#version") != std::string::npos);
    }
    SECTION("none at all") {
        writeFile(folder / "none.frag", "// nothing\n");
        const InputError error = errorOf([&] { ShaderSource::load(folder / "none.frag", {}); });
        CHECK(error.line() == 0);
        CHECK(error.message().find("found no #version") != std::string::npos);
    }
    SECTION("a second one") {
        writeFile(folder / "twice.frag", "#version 330 core\n\n#version 330 core\n");
        const InputError error = errorOf([&] { ShaderSource::load(folder / "twice.frag", {}); });
        CHECK(error.line() == 3);
    }
    SECTION("in an included file") {
        writeFile(folder / "top.frag", "#version 330 core\n#include \"lib.glsl\"\n");
        writeFile(folder / "lib.glsl", "// lib\n#version 330 core\n");
        const InputError error = errorOf([&] { ShaderSource::load(folder / "top.frag", {}); });
        CHECK(error.file() == normal(folder / "lib.glsl"));
        CHECK(error.line() == 2);
        CHECK(error.message().find("included file") != std::string::npos);
    }
}

TEST_CASE("ShaderSource: every expanded line maps back to its file and line") {
    const ShaderSource source =
        ShaderSource::load(resolveDir / "main" / "top.frag", {resolveDir / "first", resolveDir / "second"});
    checkLineMapping(source);
    const std::vector<std::string> lines = linesOf(source.text());
    const auto at = std::find(lines.begin(), lines.end(), "const int localFrom = 0;");
    REQUIRE(at != lines.end());
    const std::optional<ShaderLocation> origin = source.origin(static_cast<int>(at - lines.begin()) + 1);
    REQUIRE(origin);
    CHECK(origin->file == normal(resolveDir / "main/local.glsl"));
    CHECK(origin->line == 2);
    CHECK(source.text().find("#line") == std::string::npos); // no #line: see ShaderSource.hpp

    checkLineMapping(ShaderSource::load(shadersDir / "broken_include.frag", {}));
}

// broken_include.frag expands to 19 lines: 1-2 its #version and the stub
// #define, 3-8 color.glsl, 9-13 broken_lib.glsl, 14-19 its own lines 4-9.
TEST_CASE("ShaderSource: translateLog names the file and line for Mesa, NVIDIA and AMD logs") {
    const ShaderSource source = ShaderSource::load(shadersDir / "broken_include.frag", {});
    REQUIRE(source.files().size() == 3);
    REQUIRE(linesOf(source.text()).size() == 19);
    const std::string top = normal(shadersDir / "broken_include.frag");
    const std::string lib = normal(shadersDir / "broken_lib.glsl");

    SECTION("Mesa") {
        const std::string log = "0:12(18): error: `missingScale' undeclared\n"
                                "0:18(17): warning: something\n";
        CHECK(source.translateLog(log) == lib + ":4: error: `missingScale' undeclared\n" + top +
                                              ":8: warning: something\n");
    }
    SECTION("NVIDIA") {
        const std::string log = "0(12) : error C1008: undefined variable \"missingScale\"\n";
        CHECK(source.translateLog(log) == lib + ":4: error C1008: undefined variable \"missingScale\"\n");
    }
    SECTION("AMD") {
        CHECK(source.translateLog("ERROR: 0:12: 'missingScale' : undeclared identifier\n") ==
              lib + ":4: error: 'missingScale' : undeclared identifier\n");
    }
    SECTION("the source-string number does not matter") {
        CHECK(source.translateLog("2:12(2): error: x\n") == lib + ":4: error: x\n");
    }
    SECTION("lines without a place, and lines past the end, stay as they are") {
        const std::string log = "compilation failed\n0:99(1): error: past the end\n";
        CHECK(source.translateLog(log) == log);
    }
}

TEST_CASE("ShaderSource: firstError finds the first error's file and line") {
    const ShaderSource source = ShaderSource::load(shadersDir / "broken_include.frag", {});
    const std::string log = "0:18(3): warning: a warning first\n"
                            "0:12(18): error: `missingScale' undeclared\n"
                            "0:18(30): error: later\n";
    const std::optional<ShaderLocation> first = source.firstError(log);
    REQUIRE(first);
    CHECK(first->file == normal(shadersDir / "broken_lib.glsl"));
    CHECK(first->line == 4);

    const std::optional<ShaderLocation> onlyWarning = source.firstError("0:18(3): warning: only this\n");
    REQUIRE(onlyWarning);
    CHECK(onlyWarning->line == 8);
    CHECK_FALSE(source.firstError("nothing to see\n"));
}

TEST_CASE("ShaderSource: STOA_NOT_IMPLEMENTED stubs are listed with their function, outside comments only") {
    SECTION("a lab stub in an included file") {
        const ShaderSource source = ShaderSource::load(shadersDir / "stubbed.frag", {});
        REQUIRE(source.stubs().size() == 1);
        const ShaderStub& stub = source.stubs()[0];
        CHECK(stub.file == normal(shadersDir / "stubbed_shading.glsl"));
        CHECK(stub.line == 8);
        CHECK(stub.function == "shade");
    }
    SECTION("functions, comments and look-alikes") {
        const std::string text = "#version 330 core\n"                                       // 1
                                 "// STOA_NOT_IMPLEMENTED(commented out)\n"                   // 2
                                 "/* STOA_NOT_IMPLEMENTED(also\n"                             // 3
                                 "   STOA_NOT_IMPLEMENTED(commented) */\n"                    // 4
                                 "layout(std140) uniform Lights { vec4 color; };\n"            // 5
                                 "vec3 blinnPhong(vec3 N, vec3 L,\n"                          // 6
                                 "                vec3 V)\n"                                  // 7
                                 "{\n"                                                        // 8
                                 "    if (N.x > 0.0) { return vec3(1.0); }\n"                 // 9
                                 "    return STOA_NOT_IMPLEMENTED (vec3(0.0));\n"             // 10
                                 "}\n"                                                        // 11
                                 "float MY_STOA_NOT_IMPLEMENTED(float x) { return x; }\n"     // 12
                                 "float one() { return STOA_NOT_IMPLEMENTED(1.0); }\n"        // 13
                                 "const float k = STOA_NOT_IMPLEMENTED(2.0);\n";             // 14
        const ShaderSource source = ShaderSource::fromText(text, "inline.frag", {});
        REQUIRE(source.stubs().size() == 3);
        CHECK(source.stubs()[0].file == "inline.frag");
        CHECK(source.stubs()[0].line == 10);
        CHECK(source.stubs()[0].function == "blinnPhong");
        CHECK(source.stubs()[1].line == 13);
        CHECK(source.stubs()[1].function == "one");
        CHECK(source.stubs()[2].line == 14);
        CHECK(source.stubs()[2].function.empty());
    }
}

TEST_CASE("ShaderSource: fromText resolves includes next to its name, then along the search path") {
    const ShaderSource source = ShaderSource::fromText("#version 330 core\n#include \"color.glsl\"\n",
                                                       resolveDir / "virtual.frag", {shadersDir});
    REQUIRE(source.files().size() == 2);
    CHECK(normal(source.files()[0]) == normal(resolveDir / "virtual.frag"));
    CHECK(normal(source.files()[1]) == normal(shadersDir / "color.glsl"));
    CHECK(source.text().find("uniform vec4 uColor;") != std::string::npos);
}
