// The committed Acropolis assets (assets/acropolis/): they are exactly what the
// generator writes, every OBJ loads and is well formed, and every texture the
// materials name exists and decodes in the format the course promises.

#include "catch.hpp"
#include "MeshChecks.hpp"
#include "TempFolder.hpp"

#include <Acropolis.hpp>
#include <Sky.hpp>
#include <PortableMath.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/image/Image.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

using namespace stoa;
namespace fs = std::filesystem;

namespace {

const fs::path committedDir = paths::assetsDir() / "acropolis";

std::string readBytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

const Material& onlyMaterial(const Model& model) {
    REQUIRE(model.parts.size() == 1);
    return model.parts.front().material;
}

} // namespace

TEST_CASE("The generator reproduces the committed assets byte for byte", "[geometry][assets]") {
    test::TempFolder folder("acropolis");
    assets::generateAcropolis(folder.path());
    for (const std::string& name : assets::acropolisFileNames()) {
        INFO(name << ": regenerate with bin/stoa-generate-assets assets/acropolis (assets/README.md)");
        REQUIRE(fs::exists(committedDir / name));
        const std::string generated = readBytes(folder / name);
        CHECK(generated.size() > 0);
        const bool same = generated == readBytes(committedDir / name);
        const fs::path extension = fs::path(name).extension();
        if (!same && extension != ".obj" && extension != ".mtl") {
            // Tell a changed generator from a different stb_image_write (another
            // distribution's libstb may encode the same pixels differently).
            const Image mine = Image::load(folder / name), committed = Image::load(committedDir / name);
            const bool samePixels = mine.sizeInBytes() == committed.sizeInBytes() &&
                                    std::equal(mine.data(), mine.data() + mine.sizeInBytes(), committed.data());
            INFO((samePixels ? "same pixels, other bytes: this libstb encodes them differently"
                             : "the pixels differ: the generator changed"));
            CHECK(same);
        } else {
            CHECK(same);
        }
    }
}

TEST_CASE("The generator's portable sin, cos and exp agree with the C library", "[geometry][assets]") {
    for (double x = -50.0; x <= 50.0; x += 0.37) {
        INFO("x = " << x);
        CHECK(std::abs(assets::portableSin(x) - std::sin(x)) < 1e-11);
        CHECK(std::abs(assets::portableCos(x) - std::cos(x)) < 1e-11);
    }
    for (double x = -30.0; x <= 30.0; x += 0.29) {
        INFO("x = " << x);
        CHECK(std::abs(assets::portableExp(x) / std::exp(x) - 1.0) < 1e-13);
    }
    CHECK(assets::portableSin(0.0) == 0.0);
    CHECK(assets::portableExp(0.0) == 1.0);
    CHECK(assets::portableExp(-1000.0) == 0.0);
}

TEST_CASE("The generator reports an output folder it cannot create", "[geometry][assets]") {
    test::TempFolder folder("acropolis-bad");
    const fs::path blocker = folder.write("not-a-folder", "a file where the output folder should go");
    try {
        assets::generateAcropolis(blocker / "acropolis");
        FAIL("expected InputError");
    } catch (const InputError& error) {
        CHECK(std::string(error.what()).find((blocker / "acropolis").string()) != std::string::npos);
    }
}

TEST_CASE("Every Acropolis OBJ loads, validates and faces outward", "[geometry][assets]") {
    const std::map<std::string, std::string> materialOf{
        {"floor.obj", "floor"}, {"column.obj", "marble"}, {"wall.obj", "wall"},
        {"temple.obj", "temple"}, {"statue.obj", "statue"}};
    for (const auto& [file, material] : materialOf) {
        INFO(file);
        const Model model = loadObj(committedDir / file);
        CHECK(onlyMaterial(model).name == material);
        const Mesh& mesh = model.parts.front().mesh;
        CHECK_NOTHROW(mesh.validate(file));
        CHECK(test::firstNonUnitNormal(mesh).empty());
        CHECK(test::firstTriangleAgainstNormals(mesh).empty());
        const auto [lower, upper] = mesh.bounds();
        CHECK(lower.y == Approx(0.0f).margin(1e-4));  // everything stands on the floor
        CHECK(upper.y >= 0.0f);
    }
}

TEST_CASE("The Acropolis meshes have the promised shapes", "[geometry][assets]") {
    SECTION("the statue: 40000 triangles, closed, normals left to the loader") {
        const fs::path path = committedDir / "statue.obj";
        CHECK(readBytes(path).find("\nvn ") == std::string::npos);
        const Mesh mesh = loadObj(path).parts.front().mesh;
        CHECK(mesh.triangleCount() == 2u * assets::kStatueSlices * assets::kStatueRings);
        CHECK(mesh.triangleCount() == 40000u);
        // Indexed: one vertex per position (slices * rings, a pole and a centre).
        CHECK(mesh.vertices.size() == std::size_t(assets::kStatueSlices) * assets::kStatueRings + 2);
        CHECK(test::signedVolume(mesh) > 0.1f);  // about a body's volume, in m^3
        CHECK(mesh.bounds().second.y == Approx(1.97f).margin(1e-3));
    }
    SECTION("the column: fluted shaft sharing its vertices, about 5 m tall") {
        const Mesh mesh = loadObj(committedDir / "column.obj").parts.front().mesh;
        CHECK(mesh.bounds().second.y == Approx(5.05f).margin(1e-3));
        // A shaft of 80 x 16 shared vertices is far below 3 per triangle.
        CHECK(mesh.vertices.size() * 2 < mesh.triangleCount() * 3);
        CHECK(mesh.triangleCount() < 5000u);
    }
    SECTION("the wall and the temple are closed boxes of the stated size") {
        const Mesh wall = loadObj(committedDir / "wall.obj").parts.front().mesh;
        CHECK(test::signedVolume(wall) == Approx(8.0f * 3.0f * 0.6f).epsilon(1e-4));
        const Mesh temple = loadObj(committedDir / "temple.obj").parts.front().mesh;
        CHECK(test::signedVolume(temple) > 0.0f);
        CHECK(temple.bounds().second.y == Approx(7.3f));
        CHECK(temple.triangleCount() < 200u);
    }
    SECTION("the floor: 30 m square facing up, its texture repeating every 2 m") {
        const Mesh floor = loadObj(committedDir / "floor.obj").parts.front().mesh;
        const auto [lower, upper] = floor.bounds();
        CHECK(upper.x - lower.x == Approx(30.0f));
        CHECK(upper.z - lower.z == Approx(30.0f));
        for (const Vertex& vertex : floor.vertices) {
            CHECK(vertex.normal == glm::vec3(0.0f, 1.0f, 0.0f));
            CHECK(vertex.uv.x == Approx(vertex.position.x / 2.0f));
            CHECK(vertex.uv.y == Approx(-vertex.position.z / 2.0f));  // v up, along -Z
        }
    }
}

TEST_CASE("Every texture the Acropolis materials name exists and decodes", "[geometry][assets]") {
    struct Expected {
        const char* object;
        const char* diffuse;
        int diffuseChannels;
    };
    const Expected expected[] = {{"floor.obj", "floor_diffuse.jpg", 3},
                                 {"column.obj", "column_diffuse.png", 3},
                                 {"wall.obj", "wall_diffuse.bmp", 3},
                                 {"temple.obj", "temple_diffuse.tga", 4}};
    for (const Expected& entry : expected) {
        INFO(entry.object);
        const Material material = onlyMaterial(loadObj(committedDir / entry.object));
        CHECK(fs::path(material.diffuseMap) == committedDir / entry.diffuse);
        const Image image = Image::load(material.diffuseMap);
        CHECK(image.channels() == entry.diffuseChannels);
        CHECK((image.width() == 256 || image.width() == 512));
        CHECK(image.width() == image.height());
        CHECK(material.diffuse == glm::vec3(material.diffuse.r));  // grey: the map carries the colour
    }

    const Material marble = onlyMaterial(loadObj(committedDir / "column.obj"));
    CHECK(fs::path(marble.specularMap) == committedDir / "column_specular.png");
    CHECK(Image::load(marble.specularMap).channels() == 1);

    const Material statue = onlyMaterial(loadObj(committedDir / "statue.obj"));
    CHECK(statue.diffuseMap.empty());
    CHECK(statue.shininess == Approx(48.0f));
}

TEST_CASE("The wall's height map is an 8-bit grey PGM matching its bricks", "[geometry][assets]") {
    const Material wall = onlyMaterial(loadObj(committedDir / "wall.obj"));
    CHECK(fs::path(wall.heightMap) == committedDir / "wall_height.pgm");
    CHECK(readBytes(wall.heightMap).rfind("P5\n256 256\n255\n", 0) == 0);  // binary, 8 bits per texel
    const Image height = Image::load(wall.heightMap);
    const Image diffuse = Image::load(wall.diffuseMap);
    REQUIRE(height.channels() == 1);
    REQUIRE(height.width() == diffuse.width());
    REQUIRE(height.height() == diffuse.height());
    // Mortar (low) runs along the top row of every course, stone (high) fills the middle.
    CHECK(height.pixel(100, 0).r < 50);
    CHECK(height.pixel(100, 16).r > 150);
    // The mortar is lighter than the stones in the colour map too.
    CHECK(diffuse.pixel(100, 0).g > diffuse.pixel(100, 16).g);
}

TEST_CASE("The dense statue has about the requested triangle count", "[geometry][assets]") {
    test::TempFolder folder("acropolis-dense");
    const fs::path path = assets::generateDenseStatue(folder.path(), 10000);
    CHECK(path == folder / "statue_dense.obj");
    const Model model = loadObj(path);
    REQUIRE(model.parts.size() == 1);
    CHECK(model.parts.front().mesh.triangleCount() == 10000u);  // 4 * 50^2
    CHECK(test::firstTriangleAgainstNormals(model.parts.front().mesh).empty());
}

TEST_CASE("The generator reproduces the committed sky byte for byte, and the sky is a sky", "[geometry][assets]") {
    const fs::path committedSky = paths::assetsDir() / "sky";
    test::TempFolder folder("sky");
    assets::generateSky(folder.path());
    for (const std::string& name : assets::skyFileNames()) {
        INFO(name << ": regenerate with bin/stoa-generate-assets --sky assets/sky (assets/README.md)");
        REQUIRE(fs::exists(committedSky / name));
        const Image mine = Image::load(folder / name), committed = Image::load(committedSky / name);
        REQUIRE(mine.sizeInBytes() == committed.sizeInBytes());
        // Pixels, not bytes: another libstb may encode the same pixels differently.
        CHECK(std::equal(mine.data(), mine.data() + mine.sizeInBytes(), committed.data()));
        CHECK(committed.width() == 128);
        CHECK(committed.height() == 128);
    }
    // Overhead (the middle of +Y) is bluer than the horizon (the middle of a side
    // face's top row), and below (-Y) is earth, warmer than blue.
    const Image up = Image::load(committedSky / "py.png"), side = Image::load(committedSky / "px.png"),
                down = Image::load(committedSky / "ny.png");
    const glm::u8vec4 zenith = up.pixel(64, 64), horizon = side.pixel(64, 63), ground = down.pixel(64, 64);
    CHECK(zenith.b > zenith.r + 60);
    CHECK(horizon.b - horizon.r < zenith.b - zenith.r);
    CHECK(ground.r > ground.b);
}
