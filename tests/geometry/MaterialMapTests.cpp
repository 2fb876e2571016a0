// The texture maps of MTL materials (map_Kd, map_Ks, norm, map_bump / bump
// with -bm) and the bad input around them: missing texture files, map lines
// without a file, unknown or incomplete options, each an InputError naming the
// MTL file and line. Ends with damaged copies of a good model, which must load
// or throw InputError, never crash.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/ObjLoader.hpp>

#include <glm/geometric.hpp>

#include <random>
#include <string>

using namespace stoa;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

const std::string kTriangle = "mtllib stone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                              "usemtl stone\nf 1/1 2/2 3/3\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string normalized(const fs::path& path) { return path.lexically_normal().string(); }

/// Writes stone.mtl with `mtl` and the triangle OBJ that uses it, plus the texture files
/// the tests name (their contents do not matter: the loader only checks that they exist).
fs::path writeModel(const TempFolder& folder, const std::string& mtl) {
    for (const char* texture : {"stone.png", "stone_specular.png", "stone_normal.png", "stone_height.pgm",
                                "maps/with space.png"}) {
        folder.write(texture, "not read by the loader");
    }
    folder.write("stone.mtl", mtl);
    return folder.write("stone.obj", kTriangle);
}

/// Loads `path` expecting an InputError at `file`:`line`; returns its message.
std::string errorAt(const fs::path& path, const fs::path& file, int line) {
    try {
        (void)loadObj(path);
    } catch (const InputError& error) {
        INFO(error.what());
        CHECK(error.file() == file.string());
        CHECK(error.line() == line);
        CHECK(contains(error.what(), file.filename().string() + ":" + std::to_string(line) + ": "));
        return error.message();
    }
    FAIL("loadObj(" << path << ") did not throw an InputError");
    return "";
}

} // namespace

TEST_CASE("loadObj reads normal and height maps with the bump multiplier", "[geometry][obj][maps]") {
    TempFolder folder("material-maps");
    const fs::path path = writeModel(folder, "newmtl stone\n"
                                             "Kd 1 1 1\n"
                                             "map_Kd -o 0.5 0.5 -s 2 2 1 stone.png\n"
                                             "map_Ks -clamp on stone_specular.png\n"
                                             "norm stone_normal.png\n"
                                             "map_bump -bm 0.25 stone_height.pgm\n");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    const Material& stone = model.parts[0].material;
    CHECK(stone.diffuseMap == normalized(folder / "stone.png"));
    CHECK(stone.specularMap == normalized(folder / "stone_specular.png"));
    CHECK(stone.normalMap == normalized(folder / "stone_normal.png"));
    CHECK(stone.heightMap == normalized(folder / "stone_height.pgm"));
    CHECK(stone.bumpScale == Approx(0.25f));
}

TEST_CASE("loadObj reads bump and map_Bump as height maps, and file names with spaces", "[geometry][obj][maps]") {
    TempFolder folder("material-bump");
    SECTION("bump, with a negative multiplier") {
        const fs::path path = writeModel(folder, "newmtl stone\nbump -bm -0.5 stone_height.pgm\n");
        const Material stone = loadObj(path).parts.at(0).material;
        CHECK(stone.heightMap == normalized(folder / "stone_height.pgm"));
        CHECK(stone.bumpScale == Approx(-0.5f));
        CHECK(stone.normalMap.empty());
    }
    SECTION("map_Bump without -bm keeps the scale 1") {
        const fs::path path = writeModel(folder, "newmtl stone\nmap_Bump stone_height.pgm\n");
        const Material stone = loadObj(path).parts.at(0).material;
        CHECK(stone.heightMap == normalized(folder / "stone_height.pgm"));
        CHECK(stone.bumpScale == 1.0f);
    }
    SECTION("a name with a space, in a folder written with a backslash") {
        const fs::path path = writeModel(folder, "newmtl stone\nmap_Kd maps\\with space.png\n");
        CHECK(loadObj(path).parts.at(0).material.diffuseMap == normalized(folder / "maps" / "with space.png"));
    }
    SECTION("a material without maps has none") {
        const fs::path path = writeModel(folder, "newmtl stone\nKd 0.5 0.5 0.5\n");
        const Material stone = loadObj(path).parts.at(0).material;
        CHECK(stone.diffuseMap.empty());
        CHECK(stone.heightMap.empty());
        CHECK(stone.bumpScale == 1.0f);
    }
}

TEST_CASE("loadObj reports bad texture statements with the MTL file and line", "[geometry][obj][maps][errors]") {
    TempFolder folder("material-errors");
    const fs::path mtl = folder / "stone.mtl";
    SECTION("a diffuse map that does not exist") {
        const fs::path path = writeModel(folder, "newmtl stone\nKd 1 1 1\n\nmap_Kd lost.png\n");
        const std::string message = errorAt(path, mtl, 4);
        CHECK(contains(message, "lost.png"));
        CHECK(contains(message, "does not exist"));
    }
    SECTION("a normal map that does not exist") {
        const fs::path path = writeModel(folder, "newmtl stone\nnorm missing_normal.png\n");
        CHECK(contains(errorAt(path, mtl, 2), "missing_normal.png"));
    }
    SECTION("a height map that is a folder") {
        folder.write("maps/placeholder", "");
        const fs::path path = writeModel(folder, "newmtl stone\nmap_bump maps\n");
        CHECK(contains(errorAt(path, mtl, 2), "not a file"));
    }
    SECTION("a map without a file name") {
        const fs::path path = writeModel(folder, "newmtl stone\nmap_Ks -clamp on\n");
        CHECK(contains(errorAt(path, mtl, 2), "needs the name of a texture file"));
    }
    SECTION("an unknown option") {
        const fs::path path = writeModel(folder, "newmtl stone\nmap_Kd -shiny 2 stone.png\n");
        CHECK(contains(errorAt(path, mtl, 2), "unknown texture option '-shiny'"));
    }
    SECTION("an option without its value") {
        const fs::path path = writeModel(folder, "newmtl stone\nmap_bump -bm\n");
        CHECK(contains(errorAt(path, mtl, 2), "-bm needs 1 value"));
    }
    SECTION("a bump multiplier that is not finite") {
        const fs::path path = writeModel(folder, "newmtl stone\nmap_bump -bm nan stone_height.pgm\n");
        CHECK(contains(errorAt(path, mtl, 2), "not finite"));
    }
}

TEST_CASE("loadObj triangulates faces with more corners and keeps their winding", "[geometry][obj]") {
    TempFolder folder("material-polygon");
    const fs::path path = folder.write("pentagon.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    const Mesh& mesh = model.parts[0].mesh;
    CHECK(mesh.triangleCount() == 3);
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position, b = mesh.vertices[mesh.indices[t + 1]].position,
                        c = mesh.vertices[mesh.indices[t + 2]].position;
        CHECK(glm::cross(b - a, c - a).z > 0.0f);  // counter-clockwise seen from +Z, as written
    }
}

TEST_CASE("loadObj on damaged copies of a good model loads or throws InputError, never crashes",
          "[geometry][obj][errors]") {
    TempFolder folder("material-damage");
    const std::string mtl = "newmtl stone\nKd 0.8 0.7 0.6\nNs 20\nmap_Kd stone.png\n";
    const std::string obj = "mtllib stone.mtl\n"
                            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                            "vn 0 0 1\n"
                            "usemtl stone\n"
                            "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
                            "f -4/-4/-1 -2/-2/-1 -1/-1/-1\n";
    folder.write("stone.png", "");
    const std::string alphabet = "0123456789 /-.#\nfvtnaeNmlus";
    std::mt19937 random(20261122u);
    int loaded = 0, rejected = 0;
    for (int round = 0; round < 300; ++round) {
        const bool damageMtl = round % 3 == 0;
        std::string text = damageMtl ? mtl : obj;
        const int edits = 1 + static_cast<int>(random() % 3);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = random() % text.size();
            switch (random() % 3) {
            case 0: text[at] = alphabet[random() % alphabet.size()]; break;
            case 1: text.erase(at, 1 + random() % 4); break;
            default: text.insert(at, 1, alphabet[random() % alphabet.size()]); break;
            }
            if (text.empty()) text = "#";
        }
        folder.write("stone.mtl", damageMtl ? text : mtl);
        const fs::path path = folder.write("stone.obj", damageMtl ? obj : text);
        INFO("round " << round << ":\n" << text);
        try {
            const Model model = loadObj(path);
            for (const ModelPart& part : model.parts) CHECK_NOTHROW(part.mesh.validate("damaged"));
            ++loaded;
        } catch (const InputError& error) {
            CHECK(!error.file().empty());
            ++rejected;
        }
    }
    CHECK(loaded + rejected == 300);
    CHECK(rejected > 0);
}
