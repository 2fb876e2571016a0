// LiveShader, the program behind stoa-editor's shader panel: an edit that does
// not compile names its line and leaves the last good program drawing; a good
// edit replaces the program; saving writes the text through a temporary file.
// Every shader lives in a TempFolder, never in shaders/.

#include "GlTestSupport.hpp"
#include "TempFolder.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/editor/LiveShader.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/image/Image.hpp>

#include <sys/stat.h>

#include <fstream>
#include <sstream>

using namespace stoa;
using stoa::test::describe;
using stoa::test::near;
namespace fs = std::filesystem;

namespace {

const char* const kVertex = "#version 330 core\n"
                            "layout(location = 0) in vec2 aPosition;\n"
                            "void main() { gl_Position = vec4(aPosition, 0.0, 1.0); }\n";

/// A fragment stage that draws `colour` (a GLSL vec3), its error-prone line
/// being line 5.
std::string fragment(const std::string& colour) {
    return "#version 330 core\n"             // 1
           "// a solid colour\n"             // 2
           "out vec4 fragColor;\n"           // 3
           "void main() {\n"                 // 4
           "    fragColor = vec4(" + colour + ", 1.0);\n"   // 5
           "}\n";                            // 6
}

/// The shader folder of a test: live/solid.vert and live/solid.frag (red).
struct ShaderFolder {
    test::TempFolder folder{"live-shader"};
    fs::path vertex = folder.write("live/solid.vert", kVertex);
    fs::path fragment = folder.write("live/solid.frag", ::fragment("vec3(1.0, 0.0, 0.0)"));
};

/// The colour `program` draws over a 4x4 target with a full-screen triangle.
glm::u8vec4 drawnColour(const Program& program) {
    Framebuffer target(4, 4);
    beginPass(passInto(target, RenderState::overlay()));
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    program.use();
    test::Triangles2D({{-1.0f, -1.0f}, {3.0f, -1.0f}, {-1.0f, 3.0f}}).draw();
    return target.readColor().pixel(2, 2);
}

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

const glm::u8vec4 kRed(255, 0, 0, 255), kGreen(0, 255, 0, 255), kBlue(0, 0, 255, 255);

} // namespace

TEST_CASE("LiveShader: starts with the files' program and text") {
    HeadlessContext context;
    ShaderFolder shaders;
    LiveShader live("live/solid.vert", "live/solid.frag", {shaders.folder.path()});
    CHECK(live.fragmentFile() == shaders.fragment);
    CHECK(live.fragmentText() == readAll(shaders.fragment));
    CHECK(live.generation() == 1);
    CHECK(live.error().empty());
    CHECK(live.errorLine() == 0);
    const glm::u8vec4 colour = drawnColour(live.program());
    INFO("drawn " << describe(colour));
    CHECK(near(colour, kRed));
}

TEST_CASE("LiveShader: files that do not compile throw, naming the file and line") {
    HeadlessContext context;
    ShaderFolder shaders;
    shaders.folder.write("live/solid.frag", fragment("vec3(1.0, 0.0)"));   // a vec3 of two
    try {
        LiveShader live("live/solid.vert", "live/solid.frag", {shaders.folder.path()});
        FAIL("expected an InputError");
    } catch (const InputError& error) {
        CHECK(fs::path(error.file()).lexically_normal() == shaders.fragment.lexically_normal());
        CHECK(error.line() == 5);
    }
}

TEST_CASE("LiveShader: a failed edit names its line, the last good program keeps drawing") {
    HeadlessContext context;
    ShaderFolder shaders;
    LiveShader live("live/solid.vert", "live/solid.frag", {shaders.folder.path()});
    const GLuint good = live.program().id();

    const std::string broken = fragment("vec3(0.0, 1.0, 0.0) oops");
    CHECK_FALSE(live.setFragmentText(broken));
    CHECK(live.errorLine() == 5);
    INFO("error: " << live.error());
    CHECK(live.error().rfind(shaders.fragment.string() + ":5: ", 0) == 0);   // "FILE:5: ..."
    CHECK(live.fragmentText() == broken);   // the text as typed, to go on editing
    CHECK(live.generation() == 1);
    CHECK(live.program().id() == good);
    const glm::u8vec4 colour = drawnColour(live.program());
    INFO("drawn " << describe(colour));
    CHECK(near(colour, kRed));
    CHECK(readAll(shaders.fragment) == fragment("vec3(1.0, 0.0, 0.0)"));   // nothing saved

    SECTION("a later good edit replaces the program and clears the error") {
        CHECK(live.setFragmentText(fragment("vec3(0.0, 1.0, 0.0)")));
        CHECK(live.generation() == 2);
        CHECK(live.error().empty());
        CHECK(live.errorLine() == 0);
        const glm::u8vec4 green = drawnColour(live.program());
        INFO("drawn " << describe(green));
        CHECK(near(green, kGreen));
    }
}

TEST_CASE("LiveShader: lines are the edited text's, across an #include") {
    HeadlessContext context;
    ShaderFolder shaders;
    shaders.folder.write("live/colours.glsl", "// colours\n// for the tests\nconst vec3 kBlue = vec3(0.0, 0.0, 1.0);\n");
    LiveShader live("live/solid.vert", "live/solid.frag", {shaders.folder.path()});
    const std::string withInclude = "#version 330 core\n"        // 1
                                    "#include \"colours.glsl\"\n"  // 2
                                    "out vec4 fragColor;\n"        // 3
                                    "void main() {\n"              // 4
                                    "    fragColor = vec4(kBlue, 1.0);\n"   // 5
                                    "}\n";
    REQUIRE(live.setFragmentText(withInclude));
    CHECK(near(drawnColour(live.program()), kBlue));

    std::string broken = withInclude;
    broken.replace(broken.find("kBlue, 1.0"), 5, "kTeal");   // line 5: an unknown name
    CHECK_FALSE(live.setFragmentText(broken));
    INFO("error: " << live.error());
    CHECK(live.errorLine() == 5);
    CHECK(near(drawnColour(live.program()), kBlue));

    SECTION("an error inside the included file is named there, at line 0 of the edited text") {
        shaders.folder.write("live/colours.glsl", "// colours\nconst vec3 kBlue = vec3(0.0, 0.0);\n");
        CHECK_FALSE(live.setFragmentText(withInclude));
        INFO("error: " << live.error());
        CHECK(live.errorLine() == 0);
        CHECK(live.error().find("colours.glsl:2:") != std::string::npos);
        CHECK(near(drawnColour(live.program()), kBlue));
    }
}

TEST_CASE("LiveShader: saveToFile() replaces the file in one step") {
    HeadlessContext context;
    ShaderFolder shaders;
    LiveShader live("live/solid.vert", "live/solid.frag", {shaders.folder.path()});
    const std::string green = fragment("vec3(0.0, 1.0, 0.0)");
    REQUIRE(live.setFragmentText(green));

    struct stat before {};
    REQUIRE(stat(shaders.fragment.c_str(), &before) == 0);
    live.saveToFile();
    CHECK(readAll(shaders.fragment) == green);
    // A new file renamed over the old one (a reader never sees half a file),
    // and no temporary file left beside it.
    struct stat after {};
    REQUIRE(stat(shaders.fragment.c_str(), &after) == 0);
    CHECK(after.st_ino != before.st_ino);
    int files = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(shaders.fragment.parent_path())) {
        INFO("in the folder: " << entry.path().filename());
        CHECK((entry.path() == shaders.fragment || entry.path().filename() == "solid.vert"));
        ++files;
    }
    CHECK(files == 2);

    SECTION("the text is saved as set, compiled or not (the panel offers to save only what compiled)") {
        CHECK_FALSE(live.setFragmentText(fragment("oops")));
        live.saveToFile();
        CHECK(readAll(shaders.fragment) == fragment("oops"));
    }
    SECTION("a folder that is gone: an InputError naming the file, nothing written") {
        fs::remove_all(shaders.fragment.parent_path());
        try {
            live.saveToFile();
            FAIL("expected an InputError");
        } catch (const InputError& error) {
            CHECK(error.file() == shaders.fragment.string());
        }
        CHECK_FALSE(fs::exists(shaders.fragment.parent_path()));
    }
    SECTION("a read-only shader file is refused and left as it was (the scene files' safe save)") {
        fs::permissions(shaders.fragment, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
        REQUIRE(live.setFragmentText(fragment("vec3(1.0, 0.0, 0.0)")));
        try {
            live.saveToFile();
            FAIL("expected an InputError");
        } catch (const InputError& error) {
            CHECK(error.file() == shaders.fragment.string());
            CHECK(error.message().find("read-only") != std::string::npos);
        }
        CHECK(readAll(shaders.fragment) == green);
    }
}
