// The cache with OpenGL assets on the headless context: files rewritten on
// disk while the "program" runs, and what the next frame draws.

#include "GlTestSupport.hpp"
#include "TempFolder.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/assets/AssetCache.hpp>
#include <stoa/assets/GlAssets.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/gl/VertexArray.hpp>
#include <stoa/image/Image.hpp>

#include <algorithm>
#include <chrono>
#include <thread>

using namespace stoa;
using stoa::test::describe;
using stoa::test::glShadersDir;
namespace fs = std::filesystem;

namespace {

/// A 4x4 image of one colour, written as a PNG file.
void writePng(const fs::path& path, glm::u8vec4 colour) {
    Image image(4, 4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) image.setPixel(x, y, colour);
    fs::create_directories(path.parent_path());
    image.savePng(path);
}

/// The colour `texture` gives at the middle of the image.
glm::u8vec4 sampled(const Texture2D& texture) {
    const Program program = Program::fromFiles(glShadersDir / "fullscreen.vert", glShadersDir / "sample.frag", {});
    VertexArray empty; // core profile: a vertex array must be bound to draw
    Framebuffer target(2, 2);
    beginPass(passInto(target, RenderState::overlay()));
    texture.bind(0);
    program.use();
    program.set("uTexture", 0);
    program.set("uUv", glm::vec2(0.5f));
    empty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return target.readColor().pixel(1, 1);
}

/// The colour `program` draws over a 4x4 target.
glm::u8vec4 drawnColour(const Program& program) {
    Framebuffer target(4, 4);
    beginPass(passInto(target, RenderState::overlay()));
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    program.use();
    test::Triangles2D::rectangle(-1.0f, -1.0f, 1.0f, 1.0f).draw();
    return target.readColor().pixel(2, 2);
}

/// Updates the cache on the wall clock every 20 ms until `done()` or
/// `seconds` pass; whether `done()`.
template <typename Done>
bool updateUntil(AssetCache& cache, Done done, double seconds = 1.0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        cache.update(steadySeconds());
        if (done()) return true;
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

const glm::u8vec4 red(255, 0, 0, 255), green(0, 255, 0, 255), blue(0, 0, 255, 255);

const char* vertexShader = "#version 330 core\n"
                           "layout(location = 0) in vec2 aPosition;\n"
                           "void main() { gl_Position = vec4(aPosition, 0.0, 1.0); }\n";

} // namespace

TEST_CASE("AssetCache: a texture rewritten on disk is drawn new within a second, a broken rewrite keeps the old") {
    HeadlessContext context;
    test::TempFolder folder("assets-texture");
    const fs::path file = folder / "textures" / "marble.png";
    writePng(file, red);
    AssetCache cache(folder.path());
    addGlAssetLoaders(cache, {});
    AssetRef<Texture2D> marble = cache.get<Texture2D>("textures/marble.png");
    CHECK(sampled(*marble) == red);
    cache.update(steadySeconds());

    // Saved as an editor does: a temporary file renamed over the original.
    writePng(folder / "textures" / "marble.png.tmp", blue);
    fs::rename(folder / "textures" / "marble.png.tmp", file);
    REQUIRE(updateUntil(cache, [&] { return marble.version() == 2; }));
    CHECK(describe(sampled(*marble)) == describe(blue));
    CHECK(cache.takeLog() == std::vector<std::string>{"reloaded textures/marble.png"});

    // A broken save: the blue texture stays, and the log names the file.
    test::writeTextFile(file, "not a PNG at all");
    REQUIRE(updateUntil(cache, [&] { return !cache.errorOf("textures/marble.png").empty(); }));
    CHECK(marble.version() == 2);
    CHECK(describe(sampled(*marble)) == describe(blue));
    const std::vector<std::string> log = cache.takeLog();
    INFO(joined(log));
    REQUIRE(log.size() == 1);
    CHECK(log[0].rfind("cannot reload textures/marble.png, keeping the last good version: " + file.string(), 0) == 0);

    // The next good save replaces it.
    writePng(file, green);
    REQUIRE(updateUntil(cache, [&] { return marble.version() == 3; }));
    CHECK(describe(sampled(*marble)) == describe(green));
    CHECK(cache.errorOf("textures/marble.png").empty());
    CHECK(cache.takeLog() == std::vector<std::string>{"reloaded textures/marble.png"});
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("AssetCache: a program reloads when an #include changes, and keeps the old one on a compile error") {
    HeadlessContext context;
    test::TempFolder folder("assets-program");
    test::writeTextFile(folder / "shaders" / "editor" / "lit.vert", vertexShader);
    const fs::path fragment = folder / "shaders" / "editor" / "lit.frag";
    test::writeTextFile(fragment, "#version 330 core\n"
                                  "#include \"palette.glsl\"\n"
                                  "out vec4 fragColor;\n"
                                  "void main() { fragColor = litColour(); }\n");
    // The include lies in the search path, not next to the shader.
    const fs::path palette = folder / "common" / "palette.glsl";
    test::writeTextFile(palette, "vec4 litColour() { return vec4(1.0, 0.0, 0.0, 1.0); }\n");

    AssetCache cache(folder.path());
    addGlAssetLoaders(cache, {folder / "common"});
    AssetRef<Program> lit = cache.get<Program>("shaders/editor/lit");
    CHECK(describe(drawnColour(*lit)) == describe(red));
    const std::vector<std::string> files = cache.assets().at(0).files;
    CHECK(std::find(files.begin(), files.end(), FileWatcher::normalPath(palette)) != files.end());
    cache.update(steadySeconds());

    test::writeTextFile(palette, "vec4 litColour() { return vec4(0.0, 1.0, 0.0, 1.0); }\n");
    REQUIRE(updateUntil(cache, [&] { return lit.version() == 2; }));
    CHECK(describe(drawnColour(*lit)) == describe(green));
    CHECK(cache.takeLog() == std::vector<std::string>{"reloaded shaders/editor/lit"});

    // A compile error on line 4 of lit.frag: the green program stays.
    test::writeTextFile(fragment, "#version 330 core\n"
                                  "#include \"palette.glsl\"\n"
                                  "out vec4 fragColor;\n"
                                  "void main() { fragColor = litColour() }\n");
    REQUIRE(updateUntil(cache, [&] { return !cache.errorOf("shaders/editor/lit").empty(); }));
    CHECK(lit.version() == 2);
    CHECK(describe(drawnColour(*lit)) == describe(green));
    const std::vector<std::string> log = cache.takeLog();
    INFO(joined(log));
    REQUIRE(log.size() == 1);
    CHECK(log[0].find("cannot reload shaders/editor/lit, keeping the last good version") != std::string::npos);
    CHECK(log[0].find(fragment.string() + ":4:") != std::string::npos);

    // Mended, and the colour changed on the way.
    test::writeTextFile(fragment, "#version 330 core\n"
                                  "#include \"palette.glsl\"\n"
                                  "out vec4 fragColor;\n"
                                  "void main() { fragColor = litColour().bgra; }\n");
    REQUIRE(updateUntil(cache, [&] { return lit.version() == 3; }));
    CHECK(describe(drawnColour(*lit)) == describe(green)); // .bgra of green is green
    CHECK(cache.errorOf("shaders/editor/lit").empty());
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("AssetCache: an OBJ model lists its MTL file and maps, and reloads when a map changes") {
    HeadlessContext context;
    test::TempFolder folder("assets-model");
    test::writeTextFile(folder / "models" / "tile.obj", "mtllib tile.mtl\n"
                                                         "v 0 0 0\nv 1 0 0\nv 1 1 0\n"
                                                         "vt 0 0\nvt 1 0\nvt 1 1\n"
                                                         "usemtl tile\nf 1/1 2/2 3/3\n");
    test::writeTextFile(folder / "models" / "tile.mtl", "newmtl tile\nKd 1 1 1\nmap_Kd tile.png\n");
    writePng(folder / "models" / "tile.png", red);
    AssetCache cache(folder.path());
    addGlAssetLoaders(cache, {});
    AssetRef<GpuModel> tile = cache.get<GpuModel>("models/tile.obj");
    REQUIRE(tile->parts.size() == 1);
    CHECK(tile->parts[0].mesh->indexCount() == 3);
    REQUIRE(tile->parts[0].diffuseMap);
    CHECK(sampled(*tile->parts[0].diffuseMap) == red);
    const std::vector<std::string> expected = {FileWatcher::normalPath(folder / "models" / "tile.obj"),
                                               FileWatcher::normalPath(folder / "models" / "tile.mtl"),
                                               FileWatcher::normalPath(folder / "models" / "tile.png")};
    CHECK(cache.assets().at(0).files == expected);
    cache.update(steadySeconds());

    writePng(folder / "models" / "tile.png", blue);
    REQUIRE(updateUntil(cache, [&] { return tile.version() == 2; }));
    CHECK(describe(sampled(*tile->parts[0].diffuseMap)) == describe(blue));
}

TEST_CASE("AssetCache: the framework's own assets load by name") {
    HeadlessContext context;
    AssetCache cache(paths::sourceDir());
    addGlAssetLoaders(cache, {paths::shadersDir()});
    const AssetRef<Program> lit = cache.get<Program>("shaders/basic/lit");
    CHECK(lit->id() != 0);
    const AssetRef<GpuModel> column = cache.get<GpuModel>("assets/acropolis/column.obj");
    REQUIRE_FALSE(column->parts.empty());
    CHECK(column->parts[0].diffuseMap);
    const AssetRef<Texture2D> sky = cache.get<Texture2D>("assets/sky/nx.png");
    CHECK(sky->width() > 0);
    CHECK(cache.assets().size() == 3);
    CHECK(cache.takeLog().empty()); // no warnings
    CHECK(glGetError() == GL_NO_ERROR);
}
